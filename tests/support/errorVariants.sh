# SPDX-License-Identifier: GPL-3.0-or-later
# shellcheck shell=bash
# shellcheck disable=SC2034,SC2154
# (sourced: top and work come from caseFunctions.sh, variantPrefix from the sourcing test; bT,
# tT and props are for it)
# tests/support/errorVariants.sh: the case tests that break tutorials/twoSlabs one way at a time
# (tests/cases/errors, tests/cases/coreCrashes). Source it after caseFunctions.sh, with
# variantPrefix set (the cases are $work/$variantPrefix-base and $work/$variantPrefix-NAME).
#
# tutorials/twoSlabs is meshed once (the base, endTime lowered to 2); every variant is a copy of
# it with exactly one thing broken, and only chtMultiRegionSimpleFoam runs. A variant of kind io
# passes when the solver exits non-zero, its log has no floating-point trap (OpenFOAM's
# "sigFpe::sigHandler" in the stack, bash's "Floating point exception": bad input must be refused,
# not crash the solver; the startup line "Floating point exception trapping enabled" is no trap)
# and the error in
# its log (from the first "FOAM FATAL" line on, the case directory blanked out) holds
#   - "FOAM FATAL IO ERROR",
#   - the patch (bottom_to_top, or top_to_bottom for a variant broken on the top side),
#   - the field T: "field T" (the condition's own messages) or "/T.boundaryField." (OpenFOAM's
#     messages about the condition's dictionary name the file 0/<region>/T and the patch in it),
#   - every word of the variant's ENTRY list (the offending entry, and what identifies it), and
#   - every word of its FILE list (the file that holds the mistake),
#   - none of the words of variantForbid (a variable: e.g. bad_alloc, an allocation that failed
#     where the input should have been refused before allocating),
#   - every phrase of variantExpect (a variable, phrases separated by '|', set for one variant
#     only: words that must appear together, where the ENTRY words each appear elsewhere too).
# VARIANTS (environment, a regular expression) runs only the variants whose name it matches.
# Optional limits for every variant: variantTimeout (seconds; exit status 124 when exceeded)
# and variantMemoryKB (ulimit -v of the solver).
# Gives:
#   variant NAME KIND PATCH ENTRY FILE EDIT
#     KIND   io (above) | success (must run through) | fpe (must die by OpenFOAM's trap, SIGFPE)
#            | fatal (a function object's error: as io, but "FOAM FATAL" of either kind and
#            without the patch and the field; PATCH is ignored)
#     ENTRY, FILE  space-separated words, each of which the log must contain
#     EDIT   shell commands, run in the copy's directory, that break it
#   Prints one line per variant (name, PASS/FAIL; on FAIL what is missing and the log's last 15
#   lines).
#   variantSummary   the summary line; fails if any variant failed
#   bT, tT, props    the files variants edit: 0/bottom/T, 0/top/T, constant/thermalContactProperties
variantStarted=$SECONDS
base=$(copyCase "$top/tutorials/twoSlabs" "$variantPrefix-base")
(
    cd "$base"
    ./Allclean > /dev/null 2>&1 || true
    blockMesh > log.blockMesh 2>&1
    splitMeshRegions -cellZones -overwrite > log.splitMeshRegions 2>&1
    rm -rf 0 && cp -r 0.orig 0
    sed -i -e 's/^endTime .*/endTime         2;/' system/controlDict
    grep -q '^endTime         2;' system/controlDict
) || { echo "$variantPrefix: meshing the base case $base failed (see its log.*)" >&2; exit 1; }

bT=0/bottom/T
tT=0/top/T
props=constant/thermalContactProperties
nPass=0
nFail=0
failed=()
variantForbid=${variantForbid:-}

# has WORD: the error of the variant being checked ($dir/log.error, dynamic scope) contains WORD.
has() { grep -qF -- "$1" "$dir/log.error"; }

# errorText DIR: DIR/log from its first "FOAM FATAL" line on (or all of it, for kind fpe), with
# the case directory written as <case>: the checks must not be met by the log's earlier lines
# (the contact table's Info line names patch and field) or by the variant's name in a path.
errorText() { # DIR [all]
    awk -v dir="$1" -v all="${2:-}" '
        /FOAM FATAL/ { on = 1 }
        on || all != "" {
            out = ""
            while ((i = index($0, dir)) > 0) { out = out substr($0, 1, i - 1) "<case>"; $0 = substr($0, i + length(dir)) }
            print out $0
        }' "$1/log"
}

# runSolver DIR: the solver on DIR, within the limits, output to DIR/log; returns its status.
runSolver() {
    (
        if [ -n "${variantMemoryKB:-}" ]; then ulimit -v "$variantMemoryKB"; fi
        exec timeout "${variantTimeout:-600}" chtMultiRegionSimpleFoam -case "$1"
    ) > "$1/log" 2>&1
}

variant() {
    local name=$1 kind=$2 patch=$3 entry=$4 file=$5 edit=$6
    local dir="$work/$variantPrefix-$name" rc=0 missing=() w msg
    if [ -n "${VARIANTS:-}" ] && ! [[ $name =~ ^($VARIANTS)$ ]]; then return 0; fi
    rm -rf "$dir" && cp -r "$base" "$dir"
    if ! (cd "$dir" && eval "$edit") > "$dir/log.edit" 2>&1; then
        missing+=("the edit failed: $(tail -n 3 "$dir/log.edit")")
    else
        # The braces put bash's own report of a signal ("Aborted") into the log too.
        { runSolver "$dir" || rc=$?; } 2>> "$dir/log"
        if [ "$kind" = fpe ]; then errorText "$dir" all; else errorText "$dir"; fi > "$dir/log.error"
        [ "$rc" -ne 124 ] || missing+=("an end within ${variantTimeout:-600} s (timed out)")
        case $kind in
        success)
            [ "$rc" -eq 0 ] || missing+=("exit status 0 (got $rc)")
            ;;
        fpe)
            [ "$rc" -eq 136 ] || missing+=("death by SIGFPE, exit status 136 (got $rc)")
            has "sigFpe" || missing+=("OpenFOAM's floating-point trap (sigFpe) in the log")
            ;;
        io | fatal)
            [ "$rc" -ne 0 ] || missing+=("a non-zero exit status (the solver ran through)")
            if grep -qE "sigFpe::sigHandler|Floating point exception( \(core dumped\))?\$" "$dir/log"; then
                missing+=("no floating-point trap (the log has the trap's sigFpe::sigHandler or bash's Floating point exception)")
            fi
            if [ "$kind" = io ]; then
                has "FOAM FATAL IO ERROR" || missing+=("FOAM FATAL IO ERROR")
                has "$patch" || missing+=("the patch $patch")
                grep -qE "field T([^A-Za-z0-9_]|\$)|/T\.boundaryField\." "$dir/log.error" ||
                    missing+=("the field T")
            else
                has "FOAM FATAL" || missing+=("FOAM FATAL")
            fi
            for w in $entry; do has "$w" || missing+=("the entry word $w"); done
            for w in $file; do has "$w" || missing+=("the file $w"); done
            for w in $variantForbid; do ! has "$w" || missing+=("no '$w' in the error"); done
            local phrases phrase
            IFS='|' read -r -a phrases <<< "${variantExpect:-}"
            for phrase in "${phrases[@]}"; do
                [ -z "$phrase" ] || has "$phrase" || missing+=("the phrase \"$phrase\"")
            done
            ;;
        esac
    fi
    if [ ${#missing[@]} -eq 0 ]; then
        printf '%-28s PASS\n' "$name"
        nPass=$((nPass + 1))
    else
        msg=$(printf '%s; ' "${missing[@]}")
        printf '%-28s FAIL: missing %s\n' "$name" "${msg%; }"
        if [ -f "$dir/log" ]; then tail -n 15 "$dir/log" | sed 's/^/    | /'; fi
        nFail=$((nFail + 1))
        failed+=("$name")
    fi
}

variantSummary() {
    echo "$variantPrefix: $nPass passed, $nFail failed${failed[*]:+ (${failed[*]})}; $((SECONDS - variantStarted)) s"
    [ "$nFail" -eq 0 ]
}
