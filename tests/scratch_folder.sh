# Sourced by the shell tests after their arguments are read: a temporary folder $work, removed on
# exit, and fail MESSAGE (to stderr, exit 1). $1: a word for the folder's name.
work=$(mktemp -d "${TMPDIR:-/tmp}/hmlattice-$1-XXXXXX")
trap 'rm -rf "$work"' EXIT
fail() { echo "FAILED: $*" >&2; exit 1; }
