# Helpers shared by scripts/mutants.sh and scripts/mutants-in-diff.sh (sourced; they set
# EQUIVALENT to the list of equivalent mutants first).

# A mutant's name without its line and column, as scripts/mutants-equivalent.txt lists it:
# "core/src/hash.rs:12:5: replace + with - in mix" -> "core/src/hash.rs: replace + with - in mix".
strip_position() { sed -E 's/^([^:]+):[0-9]+:[0-9]+: /\1: /'; }
# The listed equivalent mutants' names (the part of each line before "  # ").
equivalent_names() { grep -v -e '^#' -e '^[[:space:]]*$' "$EQUIVALENT" | sed -E 's/  # .*$//'; }
# The number of non-empty lines of a file (0 when it is missing or empty).
count() { if [ -s "$1" ]; then grep -c . "$1"; else echo 0; fi; }
