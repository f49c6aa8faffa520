/* SPDX-License-Identifier: MIT */
/* The public functions issue #26 lists, called with corner values (NULL, 0,
 * INT32_MIN/MAX, counts past INT32_MAX / 2) on 1x1 and odd-stride surfaces
 * (RGB888 and GRAY8 of odd width, MONO1, bottom-up) whose pixel memory sits
 * between PROT_NONE guard pages: one byte out of bounds faults. Each case
 * runs in a child, so a crash fails that case only. Documented results
 * (-FX_EINVAL) are checked. Prints "api: N passed, N failed". */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "fixel/anim.h"
#include "fixel/circle.h"
#include "fixel/curve.h"
#include "fixel/error.h"
#include "fixel/fill.h"
#include "fixel/font.h"
#include "fixel/boxdim.h"
#include "fixel/collage.h"
#include "fixel/julia.h"
#include "fixel/koch.h"
#include "fixel/randfract.h"
#include "fixel/turtle.h"
#include "fixel/line.h"
#include "fixel/mesh.h"
#include "fixel/sprite.h"
#include "fixel/surface.h"
#include "guard.h"

static int passed, failed;
static const int32_t E[] = {INT32_MIN, INT32_MIN + 1, -65536, -1, 0, 1, 2, 65535, INT32_MAX - 1, INT32_MAX};
#define NE ((int)(sizeof E / sizeof E[0]))

#define WANT(x)                                                                   \
    do {                                                                          \
        if (!(x)) {                                                               \
            fprintf(stderr, "  %s:%d: %s\n", __FILE__, __LINE__, #x);             \
            _exit(1);                                                             \
        }                                                                         \
    } while (0)

static void nulls(const fx_surface *s)
{
    fx_ctx c;
    fx_ctx_init(&c, s);
    int32_t xy[8] = {0, 0, 1, 0, 0, 1, 1, 1};
    fx_color col[4] = {0xFFFF0000u, 0xFF00FF00u, 0xFF0000FFu, 0xFFFFFFFFu};
    fx_surface t;
    WANT(fx_surface_init(NULL, s->pixels, 1, 1, 4, FX_FMT_XRGB8888) == -FX_EINVAL);
    WANT(fx_surface_init(&t, NULL, 1, 1, 4, FX_FMT_XRGB8888) == -FX_EINVAL);
    WANT(fx_surface_init(&t, s->pixels, 1 << 30, 1, 4, FX_FMT_XRGB8888) == -FX_EINVAL);
    WANT(fx_surface_init(&t, s->pixels, INT32_MAX, 1, INT32_MAX, FX_FMT_XRGB8888) == -FX_EINVAL);
    WANT(fx_surface_init(&t, s->pixels, 0, 1, 4, FX_FMT_XRGB8888) == -FX_EINVAL);
    WANT(fx_surface_init(&t, s->pixels, 1, INT32_MIN, 4, FX_FMT_XRGB8888) == -FX_EINVAL);
    WANT(fx_format_min_stride(FX_FMT_XRGB8888, INT32_MAX) == INT32_MAX);
    fx_ctx_init(NULL, s);
    fx_ctx z;
    fx_ctx_init(&z, NULL);
    fx_fill_rect(&z, 0, 0, 10, 10); /* the empty context draws nothing */
    WANT(fx_fill_poly(&c, xy, INT32_MAX, FX_FILL_EVENODD) == -FX_EINVAL);
    WANT(fx_fill_poly(&c, NULL, 3, FX_FILL_EVENODD) == -FX_EINVAL);
    WANT(fx_fill_poly(NULL, xy, 3, FX_FILL_EVENODD) == -FX_EINVAL);
    fx_polyline(NULL, xy, 2);
    fx_polyline(&c, NULL, 2);
    fx_polyline(&c, xy, INT32_MAX);
    fx_fract_params p = {FX16_ONE, FX16_ONE / 4, 1, 1};
    WANT(fx_coastline(NULL, xy, 3, &p) == 0);
    WANT(fx_coastline(&c, NULL, 3, &p) == 0);
    WANT(fx_coastline(&c, xy, 3, NULL) == 0);
    WANT(fx_coastline(&c, xy, INT32_MAX, &p) == 0);
    WANT(fx_text(NULL, 0, 0, "x") == -FX_EINVAL);
    WANT(fx_text(&c, 0, 0, NULL) == -FX_EINVAL);
    int64_t w = -1, h = -1;
    fx_text_extent(NULL, NULL, &w, &h);
    WANT(w == 0 && h == 0);
    fx_text_extent(NULL, "abc", NULL, NULL);
    WANT(fx_bezier(NULL, xy, 3, 0) == -FX_EINVAL);
    WANT(fx_bezier(&c, NULL, 3, 0) == -FX_EINVAL);
    WANT(fx_bezier(&c, xy, INT32_MAX, 0) == -FX_EINVAL);
    fx_fill_tri_gouraud(NULL, xy, col);
    fx_fill_tri_gouraud(&c, NULL, col);
    fx_fill_tri_gouraud(&c, xy, NULL);
    fx_fill_poly_gouraud(NULL, xy, col, 4);
    fx_fill_poly_gouraud(&c, NULL, col, 4);
    fx_fill_poly_gouraud(&c, xy, NULL, 4);
    fx_fill_poly_gouraud(&c, xy, col, INT32_MIN);
    uint32_t mem[16];
    fx_sprite_save sv = {{0, 0, 0, 0}, mem, 16};
    WANT(fx_sprite_draw(NULL, 0, fx_sprite_arrow(), 0, 0, &sv) == -FX_EINVAL);
    WANT(fx_sprite_draw(s, 0, NULL, 0, 0, &sv) == -FX_EINVAL);
    WANT(fx_sprite_draw(s, 0, fx_sprite_arrow(), 0, 0, NULL) == -FX_EINVAL);
    fx_blit(NULL, 0, 0, s);
    fx_blit(s, 0, 0, NULL);
}

/* Every primitive with every pair of extreme coordinates, in both frames
 * (course mode: the surface seen bottom-up, issue #23). */
static void extremes(const fx_surface *s)
{
    fx_ctx c;
    fx_ctx_init(&c, s);
    for (int mode = 0; mode < 2; mode++) {
    WANT(fx_ctx_set_coords(&c, mode ? FX_COORDS_COURSE : FX_COORDS_SCREEN) == 0);
    for (int i = 0; i < NE; i++)
        for (int j = 0; j < NE; j++) {
            int32_t a = E[i], b = E[j];
            int32_t xy[6] = {a, b, b, a, a, a};
            fx_color col[3] = {0xFFFF0000u, 0xFF00FF00u, 0xFF0000FFu};
            fx_plot(&c, a, b);
            fx_line(&c, a, b, b, a);
            fx_fill_rect(&c, a, b, a, b);
            fx_rect_outline(&c, a, b, b, a);
            fx_circle(&c, a, b, b < 0 ? 0 : b > 4096 ? 4096 : b);
            fx_arc(&c, a, b, 3, (fx_angle)a, (fx_angle)b);
            fx_pie(&c, b, a, 3, (fx_angle)b, (fx_angle)a);
            fx_fill_tri(&c, a, b, b, a, a, a);
            fx_fill_poly(&c, xy, 3, FX_FILL_NONZERO);
            fx_polygon(&c, xy, 3);
            fx_polyline(&c, xy, 3);
            fx_bezier(&c, xy, 3, 0);
            fx_fill_tri_gouraud(&c, xy, col);
            fx_fill_poly_gouraud(&c, xy, col, 3);
            fx_text(&c, a, b, "Wg\xC3\xA9");
            fx_blit(s, a, b, s);
            uint32_t mem[FX_SPRITE_MAX * FX_SPRITE_MAX / 16];
            fx_sprite_save sv = {{0, 0, 0, 0}, mem, (uint32_t)(sizeof mem / sizeof mem[0])};
            if (fx_sprite_draw(s, 0, fx_sprite_arrow(), a, b, &sv) == 0)
                fx_sprite_restore(s, &sv);
        }
    }
    fx_fract_params p = {0, FX16_ONE, 1, 1};
    int32_t xy[6] = {INT32_MIN, 0, INT32_MAX, 0, 0, INT32_MAX};
    fx_coastline(&c, xy, 3, &p);
}

/* Issue #23's fractals on every surface: extreme rectangles, NULLs, the
 * turtle walking off the Q16.16 range. */
static void fractals(const fx_surface *s)
{
    fx_ctx c;
    fx_ctx_init(&c, s);
    uint32_t lut[1] = {0};
    fx_dwell_pal pal = {lut, 1, 65536, 0, 0};
    const fx_color basin[1] = {0xFFFFFFFFu};
    fx_fractal_view v = fx_julia_view(0, 0, -FX56_ONE, 0, 3 * FX56_ONE, s->w, s->h, 50);
    for (int i = 0; i < NE; i++)
        for (int j = 0; j < NE; j++) {
            int32_t a = E[i], b = E[j];
            fx_rect r = {a, b, b, a};
            fx_grass(&c, r, 3, 1);
            fx_fire(&c, r, FX16_ONE / 2, 1);
            fx_julia_basins(s, r, &v, &pal, basin, 1);
            WANT(fx_boxcount(s, r, 0, 1) >= 0);
            WANT(fx_boxcount(s, r, 0, b < 1 ? 1 : b) >= 0);
            fx_turtle t;
            fx_turtle_init(&t, &c, a, b, a);
            fx_turtle_forward(&t, INT32_MAX, 1);
            fx_turtle_line_rel(&t, a, b);
            fx_turtle_turn(&t, b);
            fx_turtle_koch(&t, a, 2);
            fx_turtle_hilbert(&t, b, 2, a);
            int32_t x, y;
            fx_julia_to_pixel(&v, (fx56)a * ((fx56)1 << 27), (fx56)b * ((fx56)1 << 27), &x, &y); /* |a| 2^-29 <= 4 */
        }
    WANT(fx_grass(NULL, (fx_rect){0, 0, 1, 1}, 1, 1) == -FX_EINVAL);
    WANT(fx_fire(NULL, (fx_rect){0, 0, 1, 1}, 0, 1) == -FX_EINVAL);
    WANT(fx_julia_basins(NULL, (fx_rect){0, 0, 1, 1}, &v, &pal, basin, 1) == -FX_EINVAL);
    WANT(fx_julia_basins(s, (fx_rect){0, 0, 1, 1}, NULL, &pal, basin, 1) == -FX_EINVAL);
    WANT(fx_julia_inverse_random(NULL, &v, 10, 1) == -FX_EINVAL);
    WANT(fx_julia_inverse_tree(&c, NULL, 3) == -FX_EINVAL);
    WANT(fx_julia_inverse_random(&c, &v, 1000, 1) >= 0);
    WANT(fx_boxcount(NULL, (fx_rect){0, 0, 1, 1}, 0, 1) == -FX_EINVAL);
    fx16 d;
    WANT(fx_boxdim_surface(s, (fx_rect){INT32_MIN, INT32_MIN, INT32_MAX, INT32_MAX}, 0, 1, INT32_MAX, &d, NULL, NULL) != 0 ||
         d >= 0);
    int32_t sz[2] = {1, 2}, ct[2] = {INT32_MAX, 1};
    WANT(fx_boxdim_fit(sz, ct, 2, &d) == 0);
    WANT(fx_boxdim_fit(NULL, ct, 2, &d) == -FX_EINVAL);
    WANT(fx_terrain_mesh(NULL, NULL, 0, 1, 1, 1, 0) == -FX_EINVAL);
    uint8_t t[12 * 12], w[12 * 12];
    fx_collage_result res;
    memset(t, 1, sizeof t);
    WANT(fx_collage_search(t, 12, 12, 16, w, &res) >= 0);
    WANT(fx_collage_search(NULL, 12, 12, 1, w, &res) == -FX_EINVAL);
    WANT(fx_fic_encode(NULL, 8, NULL) == -FX_EINVAL);
    WANT(fx_psnr(NULL, t, 1) == 0);
}

/* Issue #40: space-filling curve orders past their arrays, INT64 ends in
 * the Julia checks and conversions, the ball's energy on any int32 fields.
 * Under ASan a write past fx_peano_d2xy's digits is a crash. */
static void int64_corners(const fx_surface *s)
{
    (void)s;
    static const uint32_t orders[] = {0, 1, 20, 21, 31, 32, 33, 64, UINT32_MAX};
    static const uint64_t steps[] = {0, 1, ((uint64_t)1 << 62) - 1, (uint64_t)1 << 62, UINT64_MAX};
    for (size_t i = 0; i < sizeof orders / sizeof orders[0]; i++)
        for (size_t j = 0; j < sizeof steps / sizeof steps[0]; j++) {
            uint32_t x = 0, y = 0, n = orders[i];
            int rp = fx_peano_d2xy(n, steps[j], &x, &y), rh;
            WANT(n <= FX_PEANO_MAX_ORDER || rp == -FX_EINVAL);
            rh = fx_hilbert_d2xy(n, steps[j], &x, &y);
            WANT(n <= FX_HILBERT_MAX_ORDER || rh == -FX_EINVAL);
            WANT(rh == -FX_EINVAL || (n == 32 ? 1 : (uint64_t)x < ((uint64_t)1 << n)));
        }
    static const int64_t L[] = {INT64_MIN, INT64_MIN + 1, -1, 0, 1, INT64_MAX - 1, INT64_MAX};
    fx_julia_fixed fp[2];
    fx_julia_cycle cyc;
    for (int i = 0; i < 7; i++)
        for (int j = 0; j < 7; j++) {
            int far = L[i] < -1 || L[i] > 1 || L[j] < -1 || L[j] > 1;
            WANT((fx_julia_fixed_points(L[i], L[j], fp) == -FX_EINVAL) == far);
            WANT((fx_julia_attractor(L[i], L[j], &cyc) == -FX_EINVAL) == far);
            fx_fractal_view v = fx_julia_view(L[i], L[j], L[j], L[i], 4 * FX56_ONE, 8, 8, 20);
            WANT((fx_julia_check(&v) == -FX_EINVAL) == far);
            int32_t x, y;
            v = fx_julia_view(0, 0, 0, 0, 4 * FX56_ONE, 8, 8, 20);
            fx_julia_to_pixel(&v, L[i], L[j], &x, &y);
            WANT(x >= 4 - 256 && x <= 4 + 256 && y >= 4 - 256 && y <= 4 + 256);
        }
    for (int i = 0; i < NE; i++)
        for (int j = 0; j < NE; j++) {
            fx_anim_ball b = {0};
            fx_anim_ball_state st = {0};
            b.g = E[i];
            b.floor = E[j];
            st.y = E[NE - 1 - j];
            st.vy = E[NE - 1 - i];
            __extension__ __int128 ref = (__int128)b.g * ((int64_t)b.floor - st.y) + (int64_t)st.vy * st.vy / 2;
            WANT(fx_anim_ball_energy(&b, &st) == (ref > INT64_MAX ? INT64_MAX : (int64_t)ref));
        }
}

/* One vertex in 2^19 + 1 faces: the normal sums overflowed int32. */
static void valence(const fx_surface *s)
{
    (void)s;
    enum { NT = (1 << 19) + 1 };
    static fx_vec3 pos[3], nrm[3];
    static uint32_t tri[3 * NT];
    pos[1] = fx_vec3_make(FX16_ONE, 0, 0);
    pos[2] = fx_vec3_make(0, FX16_ONE, 0);
    for (int i = 0; i < NT; i++)
        tri[3 * i] = 0, tri[3 * i + 1] = 1, tri[3 * i + 2] = 2;
    fx_mesh m = {pos, nrm, tri, 3, NT, 3, NT, NULL, NULL};
    fx_mesh_compute_normals(&m);
    WANT(nrm[0].z > 0 && nrm[0].x == 0 && nrm[0].y == 0);
}

typedef struct conf {
    const char *name;
    int32_t w, h;
    fx_format f;
    int flip;
} conf;

static void run(const char *what, void (*fn)(const fx_surface *), const conf *k)
{
    fflush(stdout);
    pid_t pid = fork();
    if (pid == 0) {
        alarm(60);
        guarded g;
        if (guarded_make(&g, k->w, k->h, k->f, k->flip) < 0)
            _exit(2);
        fn(&g.s);
        guarded_free(&g);
        _exit(0);
    }
    int st;
    waitpid(pid, &st, 0);
    if (WIFEXITED(st) && WEXITSTATUS(st) == 0) {
        passed++;
    } else {
        failed++;
        printf("FAIL %s on %s: %s %d\n", what, k->name, WIFSIGNALED(st) ? "signal" : "exit",
               WIFSIGNALED(st) ? WTERMSIG(st) : WEXITSTATUS(st));
    }
}

int main(void)
{
    static const conf confs[] = {
        {"1x1 XRGB8888", 1, 1, FX_FMT_XRGB8888, 0}, {"1x1 RGB888", 1, 1, FX_FMT_RGB888, 0},
        {"1x1 MONO1", 1, 1, FX_FMT_MONO1, 0},       {"3x5 RGB888 (stride 9)", 3, 5, FX_FMT_RGB888, 0},
        {"5x3 GRAY8 (stride 5)", 5, 3, FX_FMT_GRAY8, 1}, {"7x2 RGB565 bottom-up", 7, 2, FX_FMT_RGB565, 1},
        {"9x3 MONO1", 9, 3, FX_FMT_MONO1, 0},
    };
    for (size_t i = 0; i < sizeof confs / sizeof confs[0]; i++) {
        run("NULL and count preconditions", nulls, &confs[i]);
        run("extreme coordinates", extremes, &confs[i]);
        run("issue #23 fractals", fractals, &confs[i]);
    }
    run("normals of a vertex in 2^19 + 1 faces", valence, &confs[0]);
    run("issue #40 int64 corners", int64_corners, &confs[0]);
    printf("api: %d passed, %d failed\n", passed, failed);
    return failed != 0;
}
