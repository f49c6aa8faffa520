/* SPDX-License-Identifier: MIT */
/* fixel — the textbook's Scene Description Language read into an
 * fx_rt_scene (fixel/sdl.h). Macros are not copied: a def keeps the range
 * of its body in the file text and a use reads that range through a stack
 * of frames, so every token, even one read out of a macro, has a place in
 * the file for error messages. */
#include "fixel/sdl.h"
#include "fixel/error.h"
#include "fixel/fixed.h"
#include "fixel/mesh.h"
#include "../base/fx_internal.h"

typedef struct frame {
    size_t pos, end;
    int def;       /* -1: the file itself */
    size_t use_at; /* where the use that opened it stands */
} frame;

typedef struct defn {
    size_t name, nlen, body, bend;
} defn;

/* built-in meshes, built once per file and shared by every use */
enum { M_TEAPOT, M_TETRA, M_OCTA, M_DODECA, M_ICOSA, M_BUCKY, M_COUNT };

typedef struct sdlp {
    const char *text;
    size_t len;
    const char *fname;
    const fx_sdl_env *env;
    fx_sdl_error *err;
    fx_rt_scene *s;
    frame fr[FX_SDL_MAX_NESTING + 1];
    int nfr;
    defn def[FX_SDL_MAX_DEFS];
    int ndefs;
    int32_t expanded;
    uint64_t scanned; /* bytes of macro bodies read, blanks and comments too */
    size_t tok, tlen; /* the current token */
    fx_mat4 stack[FX_SDL_STACK];
    int top;
    fx_rt_material mat;
    fx16 minr, mint;
    const fx_rt_mesh *builtin[M_COUNT];
    int nobj;
} sdlp;

static int is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f'; }
static int is_delim(char c) { return is_space(c) || c == '{' || c == '}' || c == '!'; }

/* line and column (from 1) of offset off in the file */
static void place(const sdlp *P, size_t off, int32_t *line, int32_t *col)
{
    int32_t l = 1, c = 1;
    for (size_t i = 0; i < off && i < P->len; i++) {
        if (P->text[i] == '\n')
            l++, c = 1;
        else
            c++;
    }
    *line = l, *col = c;
}

/* a token made printable and short for a message */
static const char *show(const char *t, size_t n, char *buf, size_t size)
{
    size_t k = 0;
    for (size_t i = 0; i < n && k + 4 < size; i++)
        buf[k++] = (t[i] >= 0x20 && t[i] < 0x7F) ? t[i] : '?';
    if (k < n && k + 4 <= size)
        buf[k++] = '.', buf[k++] = '.', buf[k++] = '.';
    buf[k] = 0;
    return buf;
}

static int failv(sdlp *P, size_t off, const char *fmt, va_list ap)
{
    char msg[160];
    fx_vfmt(msg, sizeof msg, fmt, ap);
    int32_t l, c;
    place(P, off, &l, &c);
    P->err->line = l, P->err->col = c;
    if (P->nfr > 1) {
        const frame *f = &P->fr[P->nfr - 1];
        const defn *d = &P->def[f->def];
        char nm[40];
        int32_t ul, uc;
        place(P, f->use_at, &ul, &uc);
        fx_fmt(P->err->msg, sizeof P->err->msg, "%s:%d:%d: %s (in 'use %s' at %d:%d)", P->fname, l, c, msg,
               show(P->text + d->name, d->nlen, nm, sizeof nm), ul, uc);
    } else {
        fx_fmt(P->err->msg, sizeof P->err->msg, "%s:%d:%d: %s", P->fname, l, c, msg);
    }
    return -FX_EINVAL;
}

static int fail(sdlp *P, size_t off, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;
static int fail(sdlp *P, size_t off, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    int e = failv(P, off, fmt, ap);
    va_end(ap);
    return e;
}

/* The next token of text[*pos, end): 1 and its range, or 0 at the end.
 * Comments run from '!' to the end of the line. */
static int scan(const char *text, size_t *pos, size_t end, size_t *b, size_t *n)
{
    size_t p = *pos;
    for (;;) {
        while (p < end && is_space(text[p]))
            p++;
        if (p < end && text[p] == '!') {
            while (p < end && text[p] != '\n')
                p++;
            continue;
        }
        break;
    }
    if (p >= end) {
        *pos = p;
        return 0;
    }
    *b = p;
    if (text[p] == '{' || text[p] == '}')
        p++;
    else
        while (p < end && !is_delim(text[p]))
            p++;
    *n = p - *b;
    *pos = p;
    return 1;
}

/* The next token through the macro frames: 1, 0 at the end of the file,
 * or an error when the expansion grows past its limit. */
static int next(sdlp *P)
{
    for (;;) {
        frame *f = &P->fr[P->nfr - 1];
        size_t from = f->pos;
        int got = scan(P->text, &f->pos, f->end, &P->tok, &P->tlen);
        /* The work of an expansion is the bytes it reads: a body of blanks
         * used many times would cost no tokens and still take minutes. A
         * frame's pos only grows within its body, and the sum is checked
         * after every step, so it stays below the limit plus one file. */
        if (P->nfr > 1) {
            P->scanned += (uint64_t)(f->pos - from);
            if (P->scanned > FX_SDL_MAX_SCAN)
                return fail(P, got ? P->tok : f->pos, "macro expansion reads more than %d bytes (the limit of one file)",
                            FX_SDL_MAX_SCAN);
        }
        if (got) {
            if (P->nfr > 1 && ++P->expanded > FX_SDL_MAX_EXPANSION)
                return fail(P, P->tok, "macro expansion longer than %d tokens (the limit of one file)",
                            FX_SDL_MAX_EXPANSION);
            return 1;
        }
        if (P->nfr == 1) {
            P->tok = P->len, P->tlen = 0;
            return 0;
        }
        P->nfr--;
    }
}

static int eq(const sdlp *P, size_t b, size_t n, const char *w)
{
    size_t i = 0;
    for (; i < n && w[i]; i++)
        if (P->text[b + i] != w[i])
            return 0;
    return i == n && !w[i];
}

static int is_tok(const sdlp *P, const char *w) { return eq(P, P->tok, P->tlen, w); }

/* A number argument of keyword kw (at kat). */
static int num(sdlp *P, const char *kw, size_t kat, fx16 *v)
{
    int e = next(P);
    if (e < 0)
        return e;
    char b[40];
    if (e == 0)
        return fail(P, kat, "%s: expected a number, found the end of the file", kw);
    e = fx16_parse(P->text + P->tok, P->tlen > 64 ? 64 : (int)P->tlen, v);
    if (e == -FX_ERANGE)
        return fail(P, P->tok, "%s: number '%s' out of range (-32768..32767)", kw,
                    show(P->text + P->tok, P->tlen, b, sizeof b));
    if (e < 0 || (size_t)e != P->tlen)
        return fail(P, P->tok, "%s: expected a number, found '%s'", kw, show(P->text + P->tok, P->tlen, b, sizeof b));
    return 0;
}

static int nums(sdlp *P, const char *kw, size_t kat, fx16 *v, int n)
{
    for (int i = 0; i < n; i++) {
        int e = num(P, kw, kat, &v[i]);
        if (e < 0)
            return e;
    }
    return 0;
}

/* A number within lo..hi, named in the error. */
static int ranged(sdlp *P, const char *kw, size_t kat, fx16 *v, fx16 lo, fx16 hi, const char *range)
{
    int e = num(P, kw, kat, v);
    if (e < 0)
        return e;
    if (*v < lo || *v > hi)
        return fail(P, P->tok, "%s: %s", kw, range);
    return 0;
}

static int colour(sdlp *P, const char *kw, size_t kat, fx3d_rgb *c)
{
    fx16 v[3];
    int e = nums(P, kw, kat, v, 3);
    if (e < 0)
        return e;
    for (int i = 0; i < 3; i++)
        if (v[i] < 0 || v[i] > FX16_ONE)
            return fail(P, kat, "%s: colour components are 0..1", kw);
    c->r = v[0], c->g = v[1], c->b = v[2];
    return 0;
}

static const char *const keywords[] = {
    "light", "globalAmbient", "background", "ambient", "diffuse", "specular", "emissive", "specularExponent",
    "reflectivity", "transparency", "speedOfLight", "minReflectivity", "minTransparency", "maxRecursionDepth",
    "defaultMaterials", "push", "pop", "translate", "scale", "rotate", "identityAffine", "sphere", "cube", "plane",
    "square", "cylinder", "cone", "taperedCylinder", "torus", "teapot", "tetrahedron", "octahedron",
    "dodecahedron", "icosahedron", "buckyball", "mesh", "union", "intersection", "difference", "def", "use",
    /* the textbook's others, refused by name */
    "diamond", "pawn", "extrude", "texturedCube", "makePixmap", "texture", "parameters", "specularFraction",
    "surfaceRoughness", NULL};

static const char *const unsupported[] = {"diamond", "pawn", "extrude", "texturedCube", "makePixmap", "texture",
                                          "parameters", "specularFraction", "surfaceRoughness", NULL};

static int is_ident(const sdlp *P, size_t b, size_t n)
{
    if (n == 0 || n > 64)
        return 0;
    for (size_t i = 0; i < n; i++) {
        char c = P->text[b + i];
        int alpha = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
        if (!alpha && !(i > 0 && c >= '0' && c <= '9'))
            return 0;
    }
    for (int k = 0; keywords[k]; k++)
        if (eq(P, b, n, keywords[k]))
            return 0;
    return 1;
}

static int find_def(const sdlp *P, size_t b, size_t n)
{
    for (int i = 0; i < P->ndefs; i++)
        if (P->def[i].nlen == n && !__builtin_memcmp(P->text + P->def[i].name, P->text + b, n))
            return i;
    return -1;
}

static int cmd_def(sdlp *P, size_t at)
{
    char b[40];
    int e = next(P);
    if (e < 0)
        return e;
    if (e == 0 || !is_ident(P, P->tok, P->tlen))
        return fail(P, e ? P->tok : at, "def: expected a name (letters, digits, _; not a keyword), found '%s'",
                    e ? show(P->text + P->tok, P->tlen, b, sizeof b) : "the end of the file");
    size_t name = P->tok, nlen = P->tlen;
    if (find_def(P, name, nlen) >= 0)
        return fail(P, name, "def %s: already defined (a name is defined once)", show(P->text + name, nlen, b, sizeof b));
    if (P->ndefs >= FX_SDL_MAX_DEFS)
        return fail(P, name, "def: more than %d definitions", FX_SDL_MAX_DEFS);
    /* the body lies in the current frame: its braces must too */
    frame *f = &P->fr[P->nfr - 1];
    size_t tb, tn;
    if (!scan(P->text, &f->pos, f->end, &tb, &tn) || !eq(P, tb, tn, "{"))
        return fail(P, name, "def %s: expected '{' after the name", show(P->text + name, nlen, b, sizeof b));
    size_t body = f->pos;
    for (;;) {
        size_t before = f->pos;
        if (!scan(P->text, &f->pos, f->end, &tb, &tn))
            return fail(P, at, "def %s: no closing '}'", show(P->text + name, nlen, b, sizeof b));
        if (eq(P, tb, tn, "{"))
            return fail(P, tb, "def %s: '{' inside a def body (defs do not nest)",
                        show(P->text + name, nlen, b, sizeof b));
        if (eq(P, tb, tn, "}")) {
            (void)before;
            P->def[P->ndefs++] = (defn){name, nlen, body, tb};
            return 0;
        }
    }
}

static int cmd_use(sdlp *P, size_t at)
{
    char b[40];
    int e = next(P);
    if (e < 0)
        return e;
    if (e == 0)
        return fail(P, at, "use: expected a name, found the end of the file");
    int d = find_def(P, P->tok, P->tlen);
    if (d < 0)
        return fail(P, P->tok, "use %s: not defined (def it before its use)",
                    show(P->text + P->tok, P->tlen, b, sizeof b));
    for (int i = 1; i < P->nfr; i++)
        if (P->fr[i].def == d)
            return fail(P, P->tok, "use %s: recursive (it is being expanded already)",
                        show(P->text + P->tok, P->tlen, b, sizeof b));
    if (P->nfr > FX_SDL_MAX_NESTING)
        return fail(P, P->tok, "use: macros nested deeper than %d", FX_SDL_MAX_NESTING);
    P->fr[P->nfr++] = (frame){P->def[d].body, P->def[d].bend, d, at};
    return 0;
}

static void mult(sdlp *P, const fx_mat4 *m)
{
    fx_mat4 t;
    fx_mat4_mul(&t, &P->stack[P->top], m);
    P->stack[P->top] = t;
}

static void default_material(fx_rt_material *m)
{
    __builtin_memset(m, 0, sizeof *m);
    m->ambient = (fx3d_rgb){FX16_ONE / 10, FX16_ONE / 10, FX16_ONE / 10};
    m->diffuse = (fx3d_rgb){FX16_ONE * 8 / 10, FX16_ONE * 8 / 10, FX16_ONE * 8 / 10};
    m->shininess = 1;
    m->ior = FX16_ONE;
    m->bump_scale = FX16_ONE;
    m->tex_scale = FX16_ONE;
}

/* An added object's index, or the error of fx_rt_add_* named at kat. */
static int added(sdlp *P, int e, const char *kw, size_t kat)
{
    if (e >= 0) {
        P->nobj++;
        return e;
    }
    if (e == -FX_ENOSPC)
        return fail(P, kat, "%s: more than %d objects (the scene's limit)", kw, P->s->cap);
    if (e == -FX_EDOM)
        return fail(P, kat, "%s: the transform is singular or scales an axis below 1/16", kw);
    if (e == -FX_ERANGE)
        return fail(P, kat, "%s: the shape leaves the scene limit (+-%d units)", kw, FX_RT_WORLD);
    if (e == -FX_E2BIG)
        return fail(P, kat, "%s: the CSG tree would be deeper than %d", kw, FX_RT_MAX_DEPTH);
    return fail(P, kat, "%s: cannot be added (%s)", kw, fx_strerror(e));
}

static void *alloc(sdlp *P, size_t n) { return P->env && P->env->alloc ? P->env->alloc(P->env->user, n) : NULL; }

/* The BVH over m (whose arrays must outlive the scene). */
static int build(sdlp *P, const fx_mesh *m, const char *kw, size_t kat, const fx_rt_mesh **out)
{
    fx_mesh *keep = alloc(P, sizeof *keep);
    fx_rt_mesh *rm = alloc(P, sizeof *rm);
    fx_rt_bvh_node *nodes = alloc(P, (size_t)m->ntris * 2 * sizeof *nodes);
    uint32_t *order = alloc(P, (size_t)m->ntris * sizeof *order);
    if (!keep || !rm || !nodes || !order)
        return fail(P, kat, "%s: out of memory for %d triangles", kw, m->ntris);
    *keep = *m;
    int e = fx_rt_mesh_build(rm, keep, nodes, m->ntris * 2, order);
    if (e == -FX_ERANGE)
        return fail(P, kat, "%s: a vertex lies beyond +-%d units", kw, FX_RT_MESH_LIMIT);
    if (e < 0)
        return fail(P, kat, "%s: the mesh cannot be built (%s)", kw, fx_strerror(e));
    *out = rm;
    return 0;
}

static int generated(sdlp *P, const fx_mesh_params *p, const char *kw, size_t kat, const fx_rt_mesh **out)
{
    int32_t nv, nt;
    if (fx_mesh_size(p, &nv, &nt) < 0)
        return fail(P, kat, "%s: bad tessellation", kw);
    fx_vec3 *mem = alloc(P, (size_t)nv * 2 * sizeof(fx_vec3) + (size_t)nt * 3 * sizeof(uint32_t));
    if (!mem)
        return fail(P, kat, "%s: out of memory for %d vertices", kw, nv);
    fx_mesh m = {mem, mem + nv, (uint32_t *)(mem + 2 * nv), nv, nt, nv, nt, NULL, NULL};
    m.nverts = m.ntris = 0;
    if (fx_mesh_make(&m, p) < 0)
        return fail(P, kat, "%s: bad tessellation", kw);
    return build(P, &m, kw, kat, out);
}

/* The buckyball (truncated icosahedron), circumradius 1: the icosahedron's
 * edges cut at their thirds give 60 vertices; each old vertex leaves a
 * pentagon, each old face a hexagon; polygons fan from their first corner,
 * turned outward. Flat faces (no vertex normals). */
static int buckyball(sdlp *P, size_t kat, const fx_rt_mesh **out)
{
    const fx16 phi = 106039; /* (1 + sqrt 5) / 2 */
    fx_vec3 ico[12];
    int k = 0;
    for (int a = -1; a <= 1; a += 2)
        for (int b = -1; b <= 1; b += 2) {
            ico[k++] = fx_vec3_make(0, a * FX16_ONE, b * phi);
            ico[k++] = fx_vec3_make(a * FX16_ONE, b * phi, 0);
            ico[k++] = fx_vec3_make(b * phi, 0, a * FX16_ONE);
        }
    /* neighbours: the edge length is 2, the next distance 2 phi */
    uint8_t adj[12][12];
    for (int i = 0; i < 12; i++)
        for (int j = 0; j < 12; j++) {
            fx_vec3 d = fx_vec3_sub(ico[i], ico[j]);
            fx16 l = fx_vec3_length(d);
            adj[i][j] = i != j && l > FX16_ONE * 3 / 2 && l < FX16_ONE * 5 / 2;
        }
    /* vertex (i, j): on the edge i-j, a third of the way from i */
    int vid[12][12];
    fx_vec3 *pos = alloc(P, 60 * sizeof *pos);
    uint32_t *tri = alloc(P, (12 * 3 + 20 * 4) * 3 * sizeof *tri);
    if (!pos || !tri)
        return fail(P, kat, "buckyball: out of memory");
    int nv = 0;
    for (int i = 0; i < 12; i++)
        for (int j = 0; j < 12; j++)
            if (adj[i][j]) {
                fx_vec3 d = fx_vec3_sub(ico[j], ico[i]);
                fx_vec3 p = fx_vec3_add(ico[i], fx_vec3_make(d.x / 3, d.y / 3, d.z / 3));
                fx_vec3_normalize(&p); /* every vertex lies on one sphere */
                vid[i][j] = nv;
                pos[nv++] = p;
            }
    int nt = 0;
    int poly[6], np;
    for (int pass = 0; pass < 2; pass++) {
        for (int i = 0; i < 12; i++)
            for (int j = 0; j < 12; j++)
                for (int l = 0; l < 12; l++) {
                    if (pass == 0) { /* pentagon about i: walk its neighbours in a ring */
                        if (j || l)
                            continue;
                        int ring[5], prev = -1, cur = -1;
                        for (int q = 0; q < 12 && cur < 0; q++)
                            if (adj[i][q])
                                cur = q;
                        for (np = 0; np < 5; np++) {
                            ring[np] = cur;
                            int nx = -1;
                            for (int q = 0; q < 12; q++)
                                if (adj[i][q] && adj[cur][q] && q != prev && nx < 0)
                                    nx = q;
                            prev = cur, cur = nx;
                        }
                        for (int q = 0; q < 5; q++)
                            poly[q] = vid[i][ring[q]];
                        np = 5;
                    } else { /* hexagon of the face i < j < l */
                        if (!(i < j && j < l && adj[i][j] && adj[j][l] && adj[i][l]))
                            continue;
                        int h[6] = {vid[i][j], vid[j][i], vid[j][l], vid[l][j], vid[l][i], vid[i][l]};
                        for (int q = 0; q < 6; q++)
                            poly[q] = h[q];
                        np = 6;
                    }
                    for (int q = 1; q + 1 < np; q++) {
                        uint32_t a = (uint32_t)poly[0], b = (uint32_t)poly[q], c = (uint32_t)poly[q + 1];
                        fx_vec3 n = fx_vec3_cross(fx_vec3_sub(pos[b], pos[a]), fx_vec3_sub(pos[c], pos[a]));
                        if (fx_vec3_dot(n, pos[a]) < 0) {
                            uint32_t t = b;
                            b = c, c = t;
                        }
                        tri[nt * 3] = a, tri[nt * 3 + 1] = b, tri[nt * 3 + 2] = c;
                        nt++;
                    }
                }
    }
    fx_mesh m = {pos, NULL, tri, nv, nt, 60, 12 * 3 + 20 * 4, NULL, NULL};
    return build(P, &m, "buckyball", kat, out);
}

/* ---- mesh FILE.3vn: "numVerts numNormals numFaces", the vertices
 * (x y z each), the normals, then each face: its corner count n, n vertex
 * indices, n normal indices (from 0). ---- */
typedef struct vn {
    sdlp *P;
    const char *t;
    size_t len, pos, b, n;
    const char *path;
    size_t kat;
} vn;

static int vn_fail(vn *V, const char *what)
{
    int32_t l = 1, c = 1;
    for (size_t i = 0; i < V->b && i < V->len; i++) {
        if (V->t[i] == '\n')
            l++, c = 1;
        else
            c++;
    }
    return fail(V->P, V->kat, "mesh: %s:%d:%d: %s", V->path, l, c, what);
}

static int vn_num(vn *V, fx16 *v)
{
    if (!scan(V->t, &V->pos, V->len, &V->b, &V->n))
        return vn_fail(V, "unexpected end of the file");
    int e = fx16_parse(V->t + V->b, V->n > 64 ? 64 : (int)V->n, v);
    if (e < 0 || (size_t)e != V->n)
        return vn_fail(V, e == -FX_ERANGE ? "number out of range" : "expected a number");
    return 0;
}

static int vn_int(vn *V, int32_t lo, int32_t hi, int32_t *v, const char *what)
{
    fx16 f;
    int e = vn_num(V, &f);
    if (e < 0)
        return e;
    if (f & 0xFFFF || (f >> 16) < lo || (f >> 16) > hi) {
        char m[96];
        fx_fmt(m, sizeof m, "%s: a whole number %d..%d", what, lo, hi);
        return vn_fail(V, m);
    }
    *v = f >> 16;
    return 0;
}

static int mesh_file(sdlp *P, size_t kat, const fx_rt_mesh **out)
{
    char b[40];
    int e = next(P);
    if (e < 0)
        return e;
    if (e == 0)
        return fail(P, kat, "mesh: expected a file name, found the end of the file");
    if (!P->env || !P->env->load_file)
        return fail(P, kat, "mesh: files not available");
    /* relative paths are taken from the SDL file's folder */
    char path[256];
    size_t k = 0, dir = 0;
    if (P->text[P->tok] != '/')
        for (size_t i = 0; P->fname[i]; i++)
            if (P->fname[i] == '/')
                dir = i + 1;
    if (dir + P->tlen + 1 > sizeof path)
        return fail(P, P->tok, "mesh: the path is too long");
    for (; k < dir; k++)
        path[k] = P->fname[k];
    for (size_t i = 0; i < P->tlen; i++)
        path[k++] = P->text[P->tok + i];
    path[k] = 0;
    const uint8_t *data;
    size_t len;
    e = P->env->load_file(P->env->user, path, &data, &len);
    if (e < 0)
        return fail(P, P->tok, "mesh: cannot read '%s': %s", show(path, k, b, sizeof b), fx_strerror(e));
    vn V = {P, (const char *)data, len, 0, 0, 0, path, kat};
    int32_t nv, nn, nf;
    if ((e = vn_int(&V, 1, FX_SDL_MESH_MAX, &nv, "numVerts")) < 0 ||
        (e = vn_int(&V, 0, FX_SDL_MESH_MAX, &nn, "numNormals")) < 0 ||
        (e = vn_int(&V, 1, FX_SDL_MESH_MAX, &nf, "numFaces")) < 0)
        return e;
    fx_vec3 *pt = alloc(P, (size_t)nv * sizeof *pt), *nm = alloc(P, ((size_t)nn + 1) * sizeof *nm);
    if (!pt || !nm)
        return fail(P, kat, "mesh: out of memory for %d vertices", nv);
    for (int32_t i = 0; i < nv + nn; i++) {
        fx16 v[3];
        for (int c = 0; c < 3; c++)
            if ((e = vn_num(&V, &v[c])) < 0)
                return e;
        if (i < nv)
            pt[i] = fx_vec3_make(v[0], v[1], v[2]);
        else
            nm[i - nv] = fx_vec3_make(v[0], v[1], v[2]);
    }
    /* first pass: check the faces and count corners and triangles */
    size_t faces = V.pos;
    int32_t corners = 0, tris = 0;
    for (int32_t f = 0; f < nf; f++) {
        int32_t n, x;
        if ((e = vn_int(&V, 3, FX_SDL_FACE_MAX, &n, "corners of a face")) < 0)
            return e;
        for (int32_t c = 0; c < n; c++)
            if ((e = vn_int(&V, 0, nv - 1, &x, "vertex index")) < 0)
                return e;
        for (int32_t c = 0; c < n; c++)
            if ((e = vn_int(&V, 0, nn > 0 ? nn - 1 : 0, &x, nn > 0 ? "normal index" : "normal index (no normals)")) <
                0)
                return e;
        corners += n, tris += n - 2;
        if (corners > FX_SDL_MESH_MAX || tris > FX_SDL_MESH_MAX)
            return fail(P, kat, "mesh: %s: more than %d corners or triangles (the limit of one mesh)", path,
                        FX_SDL_MESH_MAX);
    }
    /* second pass: one vertex per corner, with the corner's normal */
    fx_vec3 *pos = alloc(P, (size_t)corners * 2 * sizeof *pos);
    uint32_t *tri = alloc(P, (size_t)tris * 3 * sizeof *tri);
    if (!pos || !tri)
        return fail(P, kat, "mesh: out of memory for %d triangles", tris);
    fx_vec3 *nrm = nn > 0 ? pos + corners : NULL;
    V.pos = faces;
    int32_t cv = 0, ct = 0;
    for (int32_t f = 0; f < nf; f++) {
        int32_t n, x;
        vn_int(&V, 3, FX_SDL_FACE_MAX, &n, "");
        for (int32_t c = 0; c < n; c++) {
            vn_int(&V, 0, nv - 1, &x, "");
            pos[cv + c] = pt[x];
        }
        for (int32_t c = 0; c < n; c++) {
            vn_int(&V, 0, nn > 0 ? nn - 1 : 0, &x, "");
            if (nrm) {
                fx_vec3 u = nm[x];
                if (fx_vec3_normalize(&u) < 0)
                    return fail(P, kat, "mesh: %s: normal %d has no length", path, x);
                nrm[cv + c] = u;
            }
        }
        for (int32_t c = 1; c + 1 < n; c++, ct++)
            tri[ct * 3] = (uint32_t)cv, tri[ct * 3 + 1] = (uint32_t)(cv + c), tri[ct * 3 + 2] = (uint32_t)(cv + c + 1);
        cv += n;
    }
    fx_mesh m = {pos, nrm, tri, corners, tris, corners, tris, NULL, NULL};
    return build(P, &m, "mesh", kat, out);
}

static int get_object(sdlp *P, int depth, int *idx);

static int csg(sdlp *P, int depth, fx_rt_kind op, const char *kw, size_t at, int *idx)
{
    if (depth >= FX_RT_MAX_DEPTH)
        return fail(P, at, "%s: CSG nested deeper than %d", kw, FX_RT_MAX_DEPTH);
    int a, b, e = get_object(P, depth + 1, &a);
    if (e < 0)
        return e;
    if (e == 0)
        return fail(P, at, "%s: the end of the file before its first object", kw);
    if ((e = get_object(P, depth + 1, &b)) < 0)
        return e;
    if (e == 0)
        return fail(P, at, "%s: the end of the file before its second object", kw);
    e = added(P, fx_rt_add_csg(P->s, op, a, b), kw, at);
    if (e < 0)
        return e;
    P->nobj -= 2; /* its operands are no longer top-level */
    *idx = e;
    return 1;
}

/* Reads attributes until an object is complete: 1 and its index, 0 at the
 * end of the file, or an error. */
static int get_object(sdlp *P, int depth, int *idx)
{
    for (;;) {
        int e = next(P);
        if (e <= 0)
            return e;
        size_t at = P->tok;
        char b[40];
        fx16 v[6];
        if (is_tok(P, "union"))
            return csg(P, depth, FX_RT_UNION, "union", at, idx);
        if (is_tok(P, "intersection"))
            return csg(P, depth, FX_RT_INTERSECTION, "intersection", at, idx);
        if (is_tok(P, "difference"))
            return csg(P, depth, FX_RT_DIFFERENCE, "difference", at, idx);
        if (is_tok(P, "light")) {
            fx3d_rgb c;
            if ((e = nums(P, "light", at, v, 3)) < 0 || (e = colour(P, "light", at, &c)) < 0)
                return e;
            e = fx_rt_add_light(P->s, fx_vec3_make(v[0], v[1], v[2]), c, 0);
            if (e == -FX_ENOSPC)
                return fail(P, at, "light: more than %d lights (the ray tracer's limit)", FX_RT_MAX_LIGHTS);
            if (e < 0)
                return fail(P, at, "light: the position leaves the scene limit (+-%d units)", FX_RT_WORLD);
        } else if (is_tok(P, "globalAmbient")) {
            if ((e = colour(P, "globalAmbient", at, &P->s->ambient)) < 0)
                return e;
        } else if (is_tok(P, "background")) {
            if ((e = colour(P, "background", at, &P->s->background)) < 0)
                return e;
        } else if (is_tok(P, "ambient")) {
            if ((e = colour(P, "ambient", at, &P->mat.ambient)) < 0)
                return e;
        } else if (is_tok(P, "diffuse")) {
            if ((e = colour(P, "diffuse", at, &P->mat.diffuse)) < 0)
                return e;
        } else if (is_tok(P, "specular")) {
            if ((e = colour(P, "specular", at, &P->mat.specular)) < 0)
                return e;
        } else if (is_tok(P, "emissive")) {
            if ((e = colour(P, "emissive", at, &P->mat.emissive)) < 0)
                return e;
        } else if (is_tok(P, "specularExponent")) {
            if ((e = ranged(P, "specularExponent", at, v, 0, 256 * FX16_ONE, "0..256")) < 0)
                return e;
            P->mat.shininess = (v[0] + FX16_ONE / 2) >> 16;
        } else if (is_tok(P, "reflectivity")) {
            if ((e = ranged(P, "reflectivity", at, &P->mat.reflectivity, 0, FX16_ONE, "0..1")) < 0)
                return e;
        } else if (is_tok(P, "transparency")) {
            if ((e = ranged(P, "transparency", at, &P->mat.transparency, 0, FX16_ONE, "0..1")) < 0)
                return e;
        } else if (is_tok(P, "speedOfLight")) {
            /* relative to the speed outside (1): the index of refraction is its inverse */
            if ((e = ranged(P, "speedOfLight", at, v, FX16_ONE / 4, FX16_ONE,
                            "0.25..1 (the index of refraction, 1 / speedOfLight, is 1..4)")) < 0)
                return e;
            P->mat.ior = fx16_div(FX16_ONE, v[0]);
        } else if (is_tok(P, "minReflectivity") || is_tok(P, "minTransparency")) {
            int r = is_tok(P, "minReflectivity");
            if ((e = ranged(P, r ? "minReflectivity" : "minTransparency", at, v, 0, FX16_ONE, "0..1")) < 0)
                return e;
            *(r ? &P->minr : &P->mint) = v[0];
            P->s->cutoff = P->minr < P->mint ? P->minr : P->mint;
        } else if (is_tok(P, "maxRecursionDepth")) {
            if ((e = num(P, "maxRecursionDepth", at, v)) < 0)
                return e;
            if (v[0] < 0 || v[0] > FX_RT_MAX_RECURSION * FX16_ONE || (v[0] & 0xFFFF))
                return fail(P, P->tok, "maxRecursionDepth: a whole number 0..%d (the ray tracer's limit)",
                            FX_RT_MAX_RECURSION);
            P->s->max_depth = v[0] >> 16;
        } else if (is_tok(P, "defaultMaterials")) {
            default_material(&P->mat);
        } else if (is_tok(P, "push")) {
            if (P->top + 1 >= FX_SDL_STACK)
                return fail(P, at, "push: more than %d pushes without a pop", FX_SDL_STACK - 1);
            P->stack[P->top + 1] = P->stack[P->top];
            P->top++;
        } else if (is_tok(P, "pop")) {
            if (P->top == 0)
                return fail(P, at, "pop without push");
            P->top--;
        } else if (is_tok(P, "identityAffine")) {
            fx_mat4_identity(&P->stack[P->top]);
        } else if (is_tok(P, "translate") || is_tok(P, "scale")) {
            int sc = is_tok(P, "scale");
            if ((e = nums(P, sc ? "scale" : "translate", at, v, 3)) < 0)
                return e;
            fx_mat4 m;
            if (sc)
                fx_mat4_scale(&m, v[0], v[1], v[2]);
            else
                fx_mat4_translate(&m, v[0], v[1], v[2]);
            mult(P, &m);
        } else if (is_tok(P, "rotate")) {
            if ((e = nums(P, "rotate", at, v, 4)) < 0)
                return e;
            fx_mat4 m;
            if (fx_mat4_rotate(&m, fx_angle_from_deg16(v[0]), fx_vec3_make(v[1], v[2], v[3])) < 0)
                return fail(P, at, "rotate: the axis is zero");
            mult(P, &m);
        } else if (is_tok(P, "def")) {
            if ((e = cmd_def(P, at)) < 0)
                return e;
        } else if (is_tok(P, "use")) {
            if ((e = cmd_use(P, at)) < 0)
                return e;
        } else if (is_tok(P, "{")) {
            return fail(P, at, "'{' outside a def");
        } else if (is_tok(P, "}")) {
            return fail(P, at, "'}' without a def");
        } else {
            static const struct {
                const char *name;
                fx_rt_kind kind;
                fx16 s;
            } prim[] = {{"sphere", FX_RT_SPHERE, FX16_ONE},     {"cube", FX_RT_CUBE, FX16_ONE},
                        {"plane", FX_RT_PLANE, FX16_ONE},       {"square", FX_RT_SQUARE, FX16_ONE},
                        {"cylinder", FX_RT_CYLINDER, FX16_ONE}, {"cone", FX_RT_CYLINDER, 0},
                        {"torus", FX_RT_TORUS, FX16_ONE / 5}};
            for (size_t i = 0; i < sizeof prim / sizeof prim[0]; i++)
                if (is_tok(P, prim[i].name)) {
                    e = added(P, fx_rt_add_shape(P->s, prim[i].kind, prim[i].s, &P->stack[P->top], &P->mat),
                              prim[i].name, at);
                    if (e < 0)
                        return e;
                    *idx = e;
                    return 1;
                }
            if (is_tok(P, "taperedCylinder")) {
                if ((e = ranged(P, "taperedCylinder", at, v, 0, 2 * FX16_ONE,
                                "the small radius S is 0..2 (the ray tracer's limit)")) < 0)
                    return e;
                e = added(P, fx_rt_add_shape(P->s, FX_RT_CYLINDER, v[0], &P->stack[P->top], &P->mat),
                          "taperedCylinder", at);
                if (e < 0)
                    return e;
                *idx = e;
                return 1;
            }
            static const struct {
                const char *name;
                int which;
                fx_mesh_kind kind;
            } solid[] = {{"teapot", M_TEAPOT, FX_MESH_TEAPOT},
                         {"tetrahedron", M_TETRA, FX_MESH_TETRAHEDRON},
                         {"octahedron", M_OCTA, FX_MESH_OCTAHEDRON},
                         {"dodecahedron", M_DODECA, FX_MESH_DODECAHEDRON},
                         {"icosahedron", M_ICOSA, FX_MESH_ICOSAHEDRON},
                         {"buckyball", M_BUCKY, FX_MESH_KIND_COUNT},
                         {"mesh", -1, FX_MESH_KIND_COUNT}};
            for (size_t i = 0; i < sizeof solid / sizeof solid[0]; i++)
                if (is_tok(P, solid[i].name)) {
                    const fx_rt_mesh *rm = solid[i].which >= 0 ? P->builtin[solid[i].which] : NULL;
                    if (!rm) {
                        if (solid[i].which < 0)
                            e = mesh_file(P, at, &rm);
                        else if (solid[i].which == M_BUCKY)
                            e = buckyball(P, at, &rm);
                        else {
                            /* the teapot as GLUT's of size 1 (half Newell's, 1.575 tall) */
                            fx_mesh_params p = {solid[i].kind, solid[i].which == M_TEAPOT ? FX16_ONE / 2 : FX16_ONE,
                                                0, 0, solid[i].which == M_TEAPOT ? 6 : 0, 0};
                            e = generated(P, &p, solid[i].name, at, &rm);
                        }
                        if (e < 0)
                            return e;
                        if (solid[i].which >= 0)
                            P->builtin[solid[i].which] = rm;
                    }
                    e = added(P, fx_rt_add_mesh(P->s, rm, &P->stack[P->top], &P->mat), solid[i].name, at);
                    if (e < 0)
                        return e;
                    *idx = e;
                    return 1;
                }
            for (int i = 0; unsupported[i]; i++)
                if (is_tok(P, unsupported[i]))
                    return fail(P, at, "'%s' is not supported by fixel's SDL reader", unsupported[i]);
            if (P->tlen > 0 && ((P->text[at] >= '0' && P->text[at] <= '9') || P->text[at] == '-' ||
                                P->text[at] == '+' || P->text[at] == '.'))
                return fail(P, at, "a number '%s' where a keyword belongs (too many arguments before it?)",
                            show(P->text + at, P->tlen, b, sizeof b));
            return fail(P, at, "unknown keyword '%s'", show(P->text + at, P->tlen, b, sizeof b));
        }
    }
}

int fx_sdl_read(fx_rt_scene *s, const char *text, size_t len, const char *fname, const fx_sdl_env *env,
                fx_sdl_error *err)
{
    /* about 12 KB: the parser's state lives on the caller's stack */
    sdlp P;
    fx_memset(&P, 0, sizeof P);
    P.text = text, P.len = len, P.fname = fname ? fname : "-", P.env = env, P.err = err, P.s = s;
    err->msg[0] = 0, err->line = err->col = 0;
    P.fr[0] = (frame){0, len, -1, 0};
    P.nfr = 1;
    fx_mat4_identity(&P.stack[0]);
    default_material(&P.mat);
    P.minr = P.mint = s->cutoff;
    s->ambient = (fx3d_rgb){FX16_ONE / 10, FX16_ONE / 10, FX16_ONE / 10};
    s->max_depth = 3;
    for (;;) {
        int idx, e = get_object(&P, 0, &idx);
        if (e < 0)
            return e;
        if (e == 0)
            return P.nobj;
    }
}

int fx_sdl_default_camera(fx_rt_scene *s, fx16 fovy_deg)
{
    fx16 lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
    int any = 0;
    for (int i = 0; i < s->n; i++) {
        const fx_rt_object *o = &s->obj[i];
        if (!o->top || o->kind == FX_RT_PLANE)
            continue;
        for (int k = 0; k < 3; k++) {
            lo[k] = any && lo[k] < o->box.lo[k] ? lo[k] : o->box.lo[k];
            hi[k] = any && hi[k] > o->box.hi[k] ? hi[k] : o->box.hi[k];
        }
        any = 1;
    }
    if (!any)
        return fx_rt_set_camera(s, fx_vec3_make(0, 0, 5 * FX16_ONE), fx_vec3_make(0, 0, 0),
                                fx_vec3_make(0, FX16_ONE, 0), fovy_deg);
    fx_vec3 c = fx_vec3_make((fx16)(((int64_t)lo[0] + hi[0]) / 2), (fx16)(((int64_t)lo[1] + hi[1]) / 2),
                             (fx16)(((int64_t)lo[2] + hi[2]) / 2));
    fx_vec3 half = fx_vec3_make((fx16)(((int64_t)hi[0] - lo[0]) / 2), (fx16)(((int64_t)hi[1] - lo[1]) / 2),
                                (fx16)(((int64_t)hi[2] - lo[2]) / 2));
    fx16 r = fx_vec3_length(half);
    if (r < FX16_ONE / 4)
        r = FX16_ONE / 4;
    /* distance r / sin(fovy / 2), fovy within 1..179 */
    fx16 sn = fx_sin(fx_angle_from_deg16(fovy_deg / 2));
    if (sn < FX16_ONE / 128)
        sn = FX16_ONE / 128;
    int64_t d = ((int64_t)r << 16) / sn;
    fx_vec3 dir = fx_vec3_make(FX16_ONE, FX16_ONE * 6 / 5, 3 * FX16_ONE);
    fx_vec3_normalize(&dir);
    /* keep the eye within the scene limit */
    for (; d > FX16_ONE; d -= d / 8) {
        int in = 1;
        const fx16 *cc = &c.x, *dd = &dir.x;
        for (int k = 0; k < 3; k++) {
            int64_t e = cc[k] + ((d * dd[k]) >> 16);
            if (e > (int64_t)(FX_RT_WORLD - 1) * FX16_ONE || e < -(int64_t)(FX_RT_WORLD - 1) * FX16_ONE)
                in = 0;
        }
        if (in)
            break;
    }
    fx_vec3 eye = fx_vec3_add(c, fx_vec3_scale(dir, (fx16)d));
    fx16 *e = &eye.x;
    for (int k = 0; k < 3; k++) /* a scene pressed against the limit */
        e[k] = e[k] > (FX_RT_WORLD - 1) * FX16_ONE    ? (FX_RT_WORLD - 1) * FX16_ONE
               : e[k] < -(FX_RT_WORLD - 1) * FX16_ONE ? -(FX_RT_WORLD - 1) * FX16_ONE
                                                      : e[k];
    if (fx_rt_set_camera(s, eye, c, fx_vec3_make(0, FX16_ONE, 0), fovy_deg) == 0)
        return 0;
    /* the eye fell on the centre: the empty scene's camera */
    return fx_rt_set_camera(s, fx_vec3_make(0, 0, 5 * FX16_ONE), fx_vec3_make(0, 0, 0), fx_vec3_make(0, FX16_ONE, 0),
                            fovy_deg);
}
