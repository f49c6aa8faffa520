#!/bin/sh
# SPDX-License-Identifier: MIT
# The API reference, generated from the public headers' comments
# (kernel-free-src/include/fixel/*.h, boards/include/fixel/*.h):
#   --man DIR    DIR/man3/<function>.3 for every function and object the
#                headers declare, and DIR/man3/fixel.3, the overview listing
#                every one by header with its first sentence
#   --html DIR   DIR/index.html (the same overview) and DIR/<header>.html
#   --names      every documented name, one a line, sorted
#   --undocumented  the declared names whose comment is empty
# A declaration's entry is the comment block right above it; declarations
# that follow one another without a blank line share it (fx_ellipse and
# fx_fill_ellipse). A comment after the declaration on its line serves when
# there is none above. The first sentence is the one-line summary.
# make install installs the man pages; docs/api/ holds the HTML (the api
# suite, tests/api/api.sh, checks both are complete and docs/api is current).
set -eu
mode=${1:-}
out=${2:-}
case $out in ""|/*) ;; *) out=$PWD/$out ;; esac
# APIREF_ROOT: another tree (the api suite checks a header with an
# undocumented function is caught)
cd "${APIREF_ROOT:-$(dirname "$0")/../..}"
headers="$(ls kernel-free-src/include/fixel/*.h) $(ls boards/include/fixel/*.h)"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# One record a declaration: header TAB name TAB prototype TAB comment, the
# comment's lines joined by \001; header records (name "-") carry the
# header's own first comment.
awk '
function flush_decl(   s, n, i, name, rest, t) {
    s = stmt; stmt = ""
    gsub(/[ \t\n]+/, " ", s); sub(/^ /, "", s); sub(/ $/, "", s)
    # a type declared under the comment: the functions right after it share it
    if (s == "" || s ~ /^(typedef|struct|enum|union|#)/) return
    if (s ~ /^extern "C"/) return
    name = ""
    if (s ~ /\(/) {
        rest = s
        while (match(rest, /[A-Za-z_][A-Za-z0-9_]*[ ]*\(/)) {
            t = substr(rest, RSTART, RLENGTH); sub(/[ ]*\($/, "", t)
            if (t !~ /^(_|[A-Z])/ && t != "const") { name = t; break }
            rest = substr(rest, RSTART + RLENGTH)
        }
        # the prototype: up to the body or the attribute
        sub(/ *\{.*/, "", s); sub(/ *__attribute__.*/, "", s); sub(/ *#.*/, "", s)
        sub(/ *;$/, "", s); s = s ";"
    } else if (s ~ /^extern /) {
        t = s; sub(/ *(\[[^]]*\])* *;.*$/, "", t); sub(/.*[ *]/, "", t); name = t
        sub(/ *;.*$/, "", s); s = s ";"
    }
    if (name !~ /^(fx|gl|glu|glut)[A-Za-z0-9_]*$/ || name ~ /^fx_.*_t$/) { grp = ""; return }
    c = grp; if (c == "" && trail != "") c = trail
    printf "%s\t%s\t%s\t%s\n", hdr, name, s, c
}
FNR == 1 { hdr = FILENAME; sub(/.*\//, "", hdr); depth = 0; incom = 0; grp = ""; stmt = ""; first = 1; pp = 0 }
{
    line = $0
    if (incom) {
        t = line; e = index(t, "*/")
        if (e) { t = substr(t, 1, e - 1); incom = 0 }
        sub(/^[ \t]*\* ?/, "", t); sub(/[ \t]+$/, "", t)
        if (e) { if (t != "") cbuf = cbuf "\001" t; done_comment() }
        else cbuf = cbuf "\001" t
        next
    }
    if (pp) { pp = (line ~ /\\$/); next }
    # the C++ linkage wrapper is no scope
    if (line ~ /^extern "C" *\{/ || (depth == 0 && line ~ /^\}[ \t]*(\/\*.*\*\/)?[ \t]*$/)) next
    if (line ~ /^[ \t]*#/) { pp = (line ~ /\\$/); if (stmt == "") next; else next }
    if (line ~ /^[ \t]*$/) { if (depth == 0 && stmt == "") grp = ""; next }
    if (depth == 0 && stmt == "" && line ~ /^\/\*/) {
        t = substr(line, 3); e = index(t, "*/")
        if (e) { t = substr(t, 1, e - 1) }
        sub(/^ ?/, "", t); sub(/[ \t]+$/, "", t)
        cbuf = t
        if (e) done_comment(); else incom = 1
        next
    }
    # code: strip a trailing comment (kept for a declaration without one above)
    trail = ""
    if ((p = index(line, "/*")) > 0) {
        t = substr(line, p + 2); e = index(t, "*/")
        if (e) { trail = substr(t, 1, e - 1); sub(/^ +/, "", trail); sub(/ +$/, "", trail) }
        line = substr(line, 1, p - 1)
    }
    if ((p = index(line, "//")) > 0) line = substr(line, 1, p - 1)
    for (i = 1; i <= length(line); i++) {
        ch = substr(line, i, 1)
        if (ch == "{") {
            if (depth == 0 && stmt !~ /^[ \t]*(typedef|struct|enum|union)/ && stmt line ~ /\(/) {
                stmt = stmt " " substr(line, 1, i - 1); flush_decl(); injunk = 1
            }
            depth++
        } else if (ch == "}") {
            depth--
            if (depth == 0 && injunk) { injunk = 0; stmt = ""; line = substr(line, i + 1); i = 0; continue }
        } else if (ch == ";" && depth == 0) {
            if (!injunk) { stmt = stmt " " substr(line, 1, i); flush_decl() }
            line = substr(line, i + 1); i = 0; stmt = ""
            continue
        }
    }
    if (!injunk && line ~ /[^ \t]/) stmt = stmt " " line
}
function done_comment() {
    if (first) {
        first = 0; t = cbuf; sub(/^SPDX.*/, "", t)
        if (t == "") { first = 1; return }
        printf "%s\t-\t-\t%s\n", hdr, t
        return
    }
    grp = cbuf
}
' $headers > "$tmp/db"

# a declared name with no comment is undocumented
undocumented() { awk -F '\t' '$2 != "-" && $4 == "" { print $2 }' "$tmp/db" | sort -u; }

case $mode in
--names) awk -F '\t' '$2 != "-" && $4 != "" { print $2 }' "$tmp/db" | sort -u ;;
--undocumented) undocumented ;;
--db) cat "$tmp/db" ;;
--man)
    [ -n "$out" ] || { echo "usage: $0 --man DIR" >&2; exit 2; }
    mkdir -p "$out/man3"
    rm -f "$out"/man3/*.3
    version=$(sed -nE 's/^VERSION *:= *//p' Makefile)
    awk -F '\t' -v dir="$out/man3" -v version="$version" '
    function esc(s) { gsub(/\\/, "\\e", s); gsub(/\001/, "\n", s); gsub(/\n[.'"'"']/, "\n\\\\\\&&", s); sub(/^[.'"'"']/, "\\\\\\&&", s); return s }
    function summary(c,   s) {
        s = c; gsub(/\001/, " ", s); gsub(/  +/, " ", s); sub(/^fixel — /, "", s)
        if (match(s, /[.:;]( |$)/)) s = substr(s, 1, RSTART - 1)
        if (length(s) > 110) s = substr(s, 1, 107) "..."
        return s
    }
    $2 == "-" { hsum[$1] = summary($4); if (!($1 in seen)) { seen[$1] = 1; order[++nh] = $1 }; next }
    {
        if (!($1 in seen)) { seen[$1] = 1; order[++nh] = $1 }
        if ($2 in done) next
        done[$2] = 1
        names[$1] = names[$1] " " $2; sum[$2] = summary($4)
        f = dir "/" $2 ".3"
        # the others sharing the comment
        printf ".TH %s 3 \"\" \"fixel %s\" \"fixel API\"\n.SH NAME\n%s \\- %s\n", $2, version, $2, esc(sum[$2]) > f
        printf ".SH SYNOPSIS\n.nf\n.B #include <fixel/%s>\n.PP\n%s\n.fi\n", $1, esc($3) > f
        printf ".PP\nLink with \\fIpkg\\-config \\-\\-libs fixel\\fR.\n" > f
        printf ".SH DESCRIPTION\n.nf\n%s\n.fi\n", esc($4) > f
        printf ".SH SEE ALSO\n.BR fixel (3)\n" > f
        close(f)
    }
    END {
        f = dir "/fixel.3"
        printf ".TH FIXEL 3 \"\" \"fixel %s\" \"fixel API\"\n.SH NAME\nfixel \\- integer-only fixed-point graphics on Linux framebuffers: the API by header\n", version > f
        printf ".SH SYNOPSIS\n.nf\n.B #include <fixel/fixel.h>\n.fi\n(the core; the boards side has its own headers below)\n.PP\ncc prog.c $(pkg\\-config \\-\\-cflags \\-\\-libs fixel)\n" > f
        printf ".SH DESCRIPTION\nEvery public function and object, by header, with its first sentence.\nEach has its own page: \\fBman fx_line\\fR.\n" > f
        for (i = 1; i <= nh; i++) {
            h = order[i]; if (names[h] == "") continue
            printf ".SS <fixel/%s> \\(em %s\n", h, esc(hsum[h]) > f
            n = split(substr(names[h], 2), a, " ")
            for (j = 1; j <= n; j++) printf ".TP\n.B %s\n%s\n", a[j], esc(sum[a[j]]) > f
        }
        printf ".SH SEE ALSO\n.BR fixel-draw (1),\n.BR fixel-script (5),\n.BR fixel-demo (1)\n" > f
    }' "$tmp/db" ;;
--html)
    [ -n "$out" ] || { echo "usage: $0 --html DIR" >&2; exit 2; }
    mkdir -p "$out"
    rm -f "$out"/*.html
    awk -F '\t' -v dir="$out" '
    function esc(s) { gsub(/&/, "\\&amp;", s); gsub(/</, "\\&lt;", s); gsub(/>/, "\\&gt;", s); return s }
    function summary(c,   s) {
        s = c; gsub(/\001/, " ", s); gsub(/  +/, " ", s); sub(/^fixel — /, "", s)
        if (match(s, /[.:;]( |$)/)) s = substr(s, 1, RSTART - 1)
        if (length(s) > 110) s = substr(s, 1, 107) "..."
        return s
    }
    function page(h) { p = h; sub(/\.h$/, ".html", p); return p }
    function head(f, title) {
        printf "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>%s</title>\n", esc(title) > f
        printf "<style>body{font-family:sans-serif;max-width:60em;margin:auto;padding:1em}pre{background:#f4f4f4;padding:.5em;overflow-x:auto}dt{font-family:monospace;font-weight:bold}</style></head><body>\n" > f
    }
    $2 == "-" { hdoc[$1] = $4; hsum[$1] = summary($4); if (!($1 in seen)) { seen[$1] = 1; order[++nh] = $1 }; next }
    {
        if (!($1 in seen)) { seen[$1] = 1; order[++nh] = $1 }
        if (($1 SUBSEP $2) in done) next
        done[$1, $2] = 1
        names[$1] = names[$1] " " $2; sum[$2] = summary($4); proto[$2] = $3; doc[$2] = $4
    }
    END {
        f = dir "/index.html"
        head(f, "fixel API reference")
        printf "<h1>fixel API reference</h1>\n<p>Generated from the public headers by tools/gen/apiref.sh (also installed as man pages: <code>man 3 fixel</code>, <code>man fx_line</code>). Every public function and object, by header, with its first sentence.</p>\n" > f
        for (i = 1; i <= nh; i++) {
            h = order[i]; if (names[h] == "") continue
            printf "<h2><a href=\"%s\">&lt;fixel/%s&gt;</a></h2>\n<p>%s</p>\n<dl>\n", page(h), h, esc(hsum[h]) > f
            n = split(substr(names[h], 2), a, " ")
            for (j = 1; j <= n; j++) printf "<dt><a href=\"%s#%s\">%s</a></dt><dd>%s</dd>\n", page(h), a[j], a[j], esc(sum[a[j]]) > f
            printf "</dl>\n" > f
            g = dir "/" page(h)
            head(g, "<fixel/" h ">")
            d = hdoc[h]; gsub(/\001/, "\n", d)
            printf "<p><a href=\"index.html\">fixel API</a></p>\n<h1>&lt;fixel/%s&gt;</h1>\n<pre>%s</pre>\n", h, esc(d) > g
            prev = ""
            for (j = 1; j <= n; j++) {
                nm = a[j]; d = doc[nm]; gsub(/\001/, "\n", d)
                printf "<h2 id=\"%s\">%s</h2>\n<pre><code>%s</code></pre>\n", nm, nm, esc(proto[nm]) > g
                if (d != prev) printf "<pre>%s</pre>\n", esc(d) > g
                else printf "<p>(described with the function above)</p>\n" > g
                prev = d
            }
            printf "</body></html>\n" > g
            close(g)
        }
        printf "</body></html>\n" > f
    }' "$tmp/db" ;;
*) echo "usage: $0 --man DIR | --html DIR | --names | --undocumented" >&2; exit 2 ;;
esac
