// A stand-in for glog's <glog/logging.h>, enough for the pbrt-v3 sources the peer benchmark
// compiles: CHECK* abort with a message when they fail, DCHECK* are compiled out under NDEBUG
// (as glog's are), LOG(FATAL) aborts and other LOG and VLOG output is discarded.
#ifndef PEERS_GLOG_STUB_LOGGING_H
#define PEERS_GLOG_STUB_LOGGING_H

#include <cstdlib>
#include <iostream>

namespace peers_glog_stub {

// Swallows whatever is streamed into it.
struct Discard {
    template <typename T>
    Discard &operator<<(const T &) { return *this; }
    Discard &operator<<(std::ostream &(*)(std::ostream &)) { return *this; }
};

// Prints what is streamed into it, then aborts when the statement ends.
struct Fatal {
    Fatal(const char *file, int line) { std::cerr << file << ":" << line << ": "; }
    [[noreturn]] ~Fatal() {
        std::cerr << std::endl;
        std::abort();
    }
    template <typename T>
    Fatal &operator<<(const T &v) {
        std::cerr << v;
        return *this;
    }
    Fatal &operator<<(std::ostream &(*f)(std::ostream &)) {
        std::cerr << f;
        return *this;
    }
};

}  // namespace peers_glog_stub

#define PEERS_GLOG_INFO peers_glog_stub::Discard()
#define PEERS_GLOG_WARNING peers_glog_stub::Discard()
#define PEERS_GLOG_ERROR peers_glog_stub::Discard()
#define PEERS_GLOG_FATAL peers_glog_stub::Fatal(__FILE__, __LINE__)
#define LOG(severity) PEERS_GLOG_##severity
#define VLOG(level) peers_glog_stub::Discard()

#define CHECK(c) \
    while (!(c)) peers_glog_stub::Fatal(__FILE__, __LINE__) << "Check failed: " #c " "
#define CHECK_OP(a, op, b) CHECK((a)op(b))
#define CHECK_EQ(a, b) CHECK_OP(a, ==, b)
#define CHECK_NE(a, b) CHECK_OP(a, !=, b)
#define CHECK_LT(a, b) CHECK_OP(a, <, b)
#define CHECK_LE(a, b) CHECK_OP(a, <=, b)
#define CHECK_GT(a, b) CHECK_OP(a, >, b)
#define CHECK_GE(a, b) CHECK_OP(a, >=, b)

#ifdef NDEBUG
#define DCHECK(c) \
    while (false) CHECK(c)
#else
#define DCHECK(c) CHECK(c)
#endif
#define DCHECK_EQ(a, b) DCHECK((a) == (b))
#define DCHECK_NE(a, b) DCHECK((a) != (b))
#define DCHECK_LT(a, b) DCHECK((a) < (b))
#define DCHECK_LE(a, b) DCHECK((a) <= (b))
#define DCHECK_GT(a, b) DCHECK((a) > (b))
#define DCHECK_GE(a, b) DCHECK((a) >= (b))

#endif  // PEERS_GLOG_STUB_LOGGING_H
