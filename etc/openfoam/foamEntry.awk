# SPDX-License-Identifier: GPL-3.0-or-later
# foamEntry.awk: print the numbers of one entry of an OpenFOAM ascii dictionary or field file,
# one per line, at full written precision (foamDictionary rounds to 6 digits).
#   awk -v entry=boundaryField.bottom_to_top.value -f foamEntry.awk FILE
# entry is the dot-separated path of dictionary keywords. Values: `uniform X` prints X once;
# `nonuniform List<scalar> N ( ... )` prints the N values; the compact `N{X}` prints X N times;
# any other entry prints its plain numbers. Prints nothing (exit 2) if the entry is absent.
# POSIX awk (Debian's default mawk).
function isNumber(t) { return t ~ /^[-+]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][-+]?[0-9]+)?$/ }
function emit(   i, t, n, k) {
    found = 1
    for (i = 1; i <= ntok; i++) {
        t = tok[i]
        if (t == "uniform" && i < ntok) { print tok[i + 1]; return }
        if (t ~ /^List</) { if (i < ntok && isNumber(tok[i + 1])) i++; continue }
        if (isNumber(t) && i + 3 <= ntok && tok[i + 1] == "{" && tok[i + 3] == "}") {
            n = t + 0
            for (k = 0; k < n; k++) print tok[i + 2]
            i += 3
            continue
        }
        if (isNumber(t) && i < ntok && tok[i + 1] == "(") continue   # a list's count
        if (isNumber(t)) print t
    }
}
function token(t,   p, k) {
    if (!inEntry) {
        if (t == "}") { if (depth > 0) depth--; return }
        if (t == ";") return
        keyword = t; inEntry = 1; ntok = 0; paren = 0
        return
    }
    if (ntok == 0 && t == "{") { path[++depth] = keyword; inEntry = 0; return }
    if (t == "(") paren++
    if (t == ")") paren--
    if (t == ";" && paren <= 0) {
        p = keyword
        for (k = depth; k >= 1; k--) p = path[k] "." p
        if (p == entry) emit()
        inEntry = 0
        return
    }
    tok[++ntok] = t
}
BEGIN { depth = 0; inEntry = 0; inComment = 0; found = 0 }
{
    line = $0
    # Block comments (the banner), possibly across lines, then line comments.
    out = ""
    while (line != "") {
        if (inComment) {
            e = index(line, "*/")
            if (e == 0) { line = ""; break }
            line = substr(line, e + 2); inComment = 0
        } else {
            s = index(line, "/*")
            if (s == 0) { out = out line; line = ""; break }
            out = out substr(line, 1, s - 1); line = substr(line, s + 2); inComment = 1
        }
    }
    line = out
    c = index(line, "//")
    if (c > 0) line = substr(line, 1, c - 1)
    gsub(/[(){};]/, " & ", line)
    n = split(line, w, /[ \t]+/)
    for (i = 1; i <= n; i++) if (w[i] != "") token(w[i])
}
END { if (!found) exit 2 }
