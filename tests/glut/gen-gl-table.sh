#!/bin/sh
# SPDX-License-Identifier: MIT
# The GL/GLU/GLUT entry points that take float or double arguments, read
# from the layer's own headers (so the table cannot drift from the API):
# one wrapper per function calling it from an fxgl_args, and the table
# fxgl_entries[] of tests/glut/gl-hostile.h. Used by the corner test
# (tests/glut/gl-corners.c) and the fuzz target (tests/fuzz/fuzz_gl.c).
#   sh tests/glut/gen-gl-table.sh boards/glut/include/GL/*.h > gl_table.h
# A parameter type it does not know leaves the function out, named in a
# comment of the output (and counted in fxgl_skipped).
cat "$@" | awk '
function trim(s) { sub(/^[ \t]+/, "", s); sub(/[ \t]+$/, "", s); return s }
# one parameter "const GLfloat *params" -> kind letter; name in PNAME
function kind(p,   t, n) {
    p = trim(p)
    if (p == "void" || p == "") return ""
    n = p; sub(/.*[ *]/, "", n); sub(/\[.*/, "", n); PNAME = n
    t = p; if (p ~ /\[/) { sub(/[A-Za-z_0-9]*\[.*/, "", t); t = t "*" } else sub(/[A-Za-z_0-9]+$/, "", t)
    gsub(/[ \t]+/, "", t)
    if (t ~ /^(GLfloat|GLclampf|float)$/) return "f"
    if (t ~ /^(GLdouble|GLclampd|double)$/) return "d"
    if (t ~ /^(const)?(GLfloat|float)\*$/) return "F"
    if (t ~ /^(const)?(GLdouble|double)\*$/) return "D"
    if (t == "GLenum") return "e"
    if (t ~ /^(GLint|GLsizei|int|GLuint|GLshort|GLushort|GLbitfield|GLboolean|GLubyte|unsignedint)$/) return "i"
    if (t ~ /^(const)?(GLint|GLuint)\*$/) return "I"
    if (t ~ /^(const)?(GLubyte|unsignedchar|GLvoid|void|char)\*$/) return (n == "font" ? "T" : "B")
    if (t == "GLUquadric*") return "Q"
    return "?"
}
/^(GLAPI|FGAPI)/ { buf = $0; collecting = 1 }
collecting && !/^(GLAPI|FGAPI)/ { buf = buf " " $0 }
collecting && /;/ {
    collecting = 0
    s = buf; sub(/^.*(GLAPIENTRY|FGAPIENTRY)[ \t]*/, "", s)
    name = s; sub(/[ \t]*\(.*/, "", name)
    args = s; sub(/^[^(]*\(/, "", args); sub(/\)[ \t]*;.*$/, "", args)
    if (seen[name]++) next
    n = split(args, a, ",")
    sig = ""; names = ""; bad = ""
    for (i = 1; i <= n; i++) {
        k = kind(a[i])
        if (k == "?") bad = bad " " trim(a[i])
        sig = sig k
        if (k != "") names = names (names == "" ? "" : ",") PNAME
    }
    if (sig !~ /[fdFD]/) next
    if (bad != "") { print "/* left out: " name " (" trim(bad) ") */"; skipped++; next }
    # the call: f, d from a->d[], ints from a->i[], enums from a->e[], pointers to the buffers
    call = ""; nd = 0; ni = 0; ne = 0
    for (i = 1; i <= length(sig); i++) {
        k = substr(sig, i, 1)
        if (k == "f") c = "(float)a->d[" nd++ "]"
        else if (k == "d") c = "a->d[" nd++ "]"
        else if (k == "F") { c = "a->fa"; nd++ }
        else if (k == "D") { c = "a->da"; nd++ }
        else if (k == "i") c = "a->i[" ni++ "]"
        else if (k == "I") c = "a->ia"
        else if (k == "e") c = "a->e[" ne++ "]"
        else if (k == "B") c = "(void *)a->bytes"
        else if (k == "T") c = "a->font"
        else if (k == "Q") c = "a->quad"
        call = call (call == "" ? "" : ", ") c
    }
    printf "static void fxgl_call_%s(fxgl_args *a) { (void)a; %s(%s); }\n", name, name, call
    ent[++ne_total] = sprintf("    {\"%s\", \"%s\", \"%s\", fxgl_call_%s},", name, sig, names, name)
}
END {
    print "static const fxgl_entry fxgl_entries[] = {"
    for (i = 1; i <= ne_total; i++) print ent[i]
    print "};"
    printf "enum { fxgl_nentries = %d, fxgl_skipped = %d };\n", ne_total, skipped + 0
}'
