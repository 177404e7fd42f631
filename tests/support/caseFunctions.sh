# SPDX-License-Identifier: GPL-3.0-or-later
# shellcheck shell=bash
# tests/support/caseFunctions.sh: shared by the case tests under tests/cases (bash; source it).
# Sets up the project's OpenFOAM environment and gives:
#   copyCase SRC NAME   copy a tutorial as a user would (cp -r) to $work/NAME, cleaned, and print
#                       its path
#   runCase DIR         Allclean + Allrun of a case, output to DIR/log.Allrun; on failure the
#                       log's tail goes to stderr
#   numbers FILE ENTRY  every number of a field file's entry (a dot-separated keyword path,
#                       e.g. internalField or boundaryField.bottom_to_top.value), one per line
#                       at full written precision; uniform values once, lists in order
#                       (etc/openfoam/foamEntry.awk)
#   latestTime DIR      the largest numeric time directory of a case
#   compareNumbers LABEL LIMIT FILE_A FILE_B
#                       largest |a - b| / |b| over two equally long number lists (files, one
#                       number per line); prints it with LABEL; fails when over LIMIT, when
#                       the lengths differ or when a list is empty
set -euo pipefail
top=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
work=${ROUGHCONTACT_CASE_DIR:-$top/build/cases}
mkdir -p "$work"
# shellcheck source=../../etc/openfoam/environment
source "$top/etc/openfoam/environment"

copyCase() { # SRC NAME
    local dest="$work/$2"
    rm -rf "$dest" && cp -r "$1" "$dest"
    # A tutorial run in the source tree leaves results and logs; the copy starts clean.
    "$dest/Allclean" > /dev/null 2>&1 || true
    rm -f "$dest"/log.*
    echo "$dest"
}

runCase() { # DIR
    "$1/Allclean" > /dev/null 2>&1 || true
    if ! "$1/Allrun" > "$1/log.Allrun" 2>&1; then
        echo "runCase: $1/Allrun failed; last lines of its logs:" >&2
        tail -n 30 "$1/log.Allrun" >&2
        local last
        last=$(ls -t "$1"/log.* 2> /dev/null | head -n 1)
        [ -n "$last" ] && tail -n 30 "$last" >&2
        return 1
    fi
}

numbers() { # FILE ENTRY
    awk -v entry="$2" -f "$top/etc/openfoam/foamEntry.awk" "$1" || {
        echo "numbers: no entry $2 in $1" >&2
        return 1
    }
}

latestTime() { # DIR
    find "$1" -maxdepth 1 -regextype posix-extended -regex '.*/[0-9]+(\.[0-9]+)?(e[-+]?[0-9]+)?' -printf '%f\n' |
        sort -g | tail -n 1
}

compareNumbers() { # LABEL LIMIT FILE_A FILE_B
    local na nb
    na=$(wc -l < "$3"); nb=$(wc -l < "$4")
    if [ "$na" -ne "$nb" ] || [ "$na" -eq 0 ]; then
        echo "$1: $na values against $nb" >&2
        return 1
    fi
    paste "$3" "$4" | awk -v label="$1" -v limit="$2" '
        { d = $1 - $2; if (d < 0) d = -d; s = $2; if (s < 0) s = -s
          r = (s > 0) ? d / s : d; if (r > worst) { worst = r; at = NR }; n++ }
        END { printf "%s: %d values, largest relative difference %.3g (at value %d; limit %s)\n", label, n, worst, at, limit
              exit !(worst <= limit + 0) }'
}

compareEntries() { # LABEL LIMIT FILE_A FILE_B ENTRY [ENTRY ...]: compareNumbers over the entries
    local label=$1 limit=$2 a=$3 b=$4
    shift 4
    local ta="$work/.compare.a.$$" tb="$work/.compare.b.$$" e
    : > "$ta"; : > "$tb"
    for e in "$@"; do
        numbers "$a" "$e" >> "$ta"
        numbers "$b" "$e" >> "$tb"
    done
    local status=0
    compareNumbers "$label" "$limit" "$ta" "$tb" || status=1
    rm -f "$ta" "$tb"
    return $status
}
