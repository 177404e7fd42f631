# SPDX-License-Identifier: GPL-3.0-or-later
# shellcheck shell=bash
# tests/support/boundaryElementCase.sh: shared by the boundaryElement case tests (source it after
# caseFunctions.sh). Gives
#   bemCase NAME [EXTRA-LINES]  tutorials/twoSlabs copied to $work/NAME with the pressure
#                               $bemPressure Pa (1e8: A_r/A_n 0.06, some 260 contact points of
#                               4096) and the contact entry 'slabs' of model boundaryElement on a
#                               synthesized power law (the surface of the CLI call in bemCli),
#                               minPressure $bemPressure (the case's pressure is the table's first
#                               point) unless EXTRA-LINES say otherwise; prints its path
#   bemTable DIR                the case's cache file
#   bemCli LOADS                multiscaleContact --model boundaryElement on the same surface and
#                               materials at the comma-separated loads F/(A_n E'): its CSV
#   bemLoads FILE               the loads P/E' of a cache file's pressures, comma separated
#   interfaceH DIR              h on the bottom side of the interface at the latest time
bemPressure=1e8
bemSurfaceDict='    surface     { type powerLaw; bm 2.56e-4; m 0.8; fmin 1e3; fmax 32e3; length 1e-3; }
    synthesize  64;
    seed        1;'
bemSurfaceCli=(--power-law 2.56e-4,0.8,1e3,32e3 --length 1e-3 --synthesize 64,1)
cli=${cli:-$top/build/bin/multiscaleContact}

bemCase() { # NAME [EXTRA-LINES]
    local case extra=${2:-    minPressure $bemPressure;}
    case=$(copyCase "$top/tutorials/twoSlabs" "$1")
    sed -i "s/pressure        constant 1e6;/pressure        constant $bemPressure;/" "$case"/0.orig/*/T
    cat > "$case/constant/thermalContactProperties" <<EOD
FoamFile { version 2.0; format ascii; class dictionary; object thermalContactProperties; }
slabs
{
    model       boundaryElement;
$bemSurfaceDict
$extra
    side1       { E 200e9; nu 0.3; Sy 0.4e9; }
    side2       { E 200e9; nu 0.3; Sy 0.4e9; }
}
EOD
    echo "$case"
}

bemTable() { echo "$1/constant/boundaryElementTable.slabs.csv"; }

bemCli() { # LOADS
    "$cli" "${bemSurfaceCli[@]}" --model boundaryElement --E 200e9,200e9 --nu 0.3,0.3 --loads "$1"
}

bemLoads() { # FILE: P / E' with E' = 1/(2 (1 - nu^2)/E) of the two steels
    awk -F, '/^[0-9]/ { printf "%s%.17g", (n++ ? "," : ""), $1 / (1 / (2 * (1 - 0.3 * 0.3) / 200e9)) } END { print "" }' "$1"
}

interfaceH() { # DIR
    numbers "$1/$(latestTime "$1")/bottom/contactConductance" boundaryField.bottom_to_top.value | head -n 1
}
