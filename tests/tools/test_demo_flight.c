/* SPDX-License-Identifier: MIT */
/* fixel-demo's camera flight (tools/fixel-demo/page_anim.c): keys recorded
 * with 'k' go to the --flight file, a fresh page loads the same keys from
 * it, and 'g' flies the camera through them, on each recorded view exactly
 * at its key time (1.5 s apart, 45 frames at 30 a second) and resting on the
 * last one. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "fx_test.h"
#include "../../tools/fixel-demo/page_anim.c"

/* page_anim.c's only call into the rest of the demo */
void demo_text(const fx_ctx *c, int32_t x, int32_t y, fx_color col, const char *fmt, ...)
{
    (void)c, (void)x, (void)y, (void)col, (void)fmt;
}

static void press(demo_state *st, const char *keys)
{
    for (; *keys; keys++)
        FX_CHECK(demo_anim_key(st, *keys));
}

static int eye_is(const demo_state *st, const fx_anim_key *k)
{
    return st->acam.eye.x == k->v[0] && st->acam.eye.y == k->v[1] && st->acam.eye.z == k->v[2];
}

FX_TEST(demo_flight_records_to_its_file_and_plays_back)
{
    char path[] = "/tmp/fixel-flight-XXXXXX";
    int fd = mkstemp(path);
    FX_CHECK(fd >= 0);
    close(fd);
    unlink(path); /* a new file: the flight starts empty */
    static demo_state st, st2;
    memset(&st, 0, sizeof st);
    st.interactive = 1;
    demo_anim_set_file(path);
    demo_anim_init(&st);
    FX_CHECK_EQ(st.nflight, 0);
    press(&st, "kffyykhhYuk");
    FX_CHECK_EQ(st.nflight, 3);
    FX_CHECK(!eye_is(&st, &st.flight[0]) || !eye_is(&st, &st.flight[1]));
    FILE *f = fopen(path, "r");
    int lines = 0, ch;
    while (f && (ch = fgetc(f)) != EOF)
        lines += ch == '\n';
    if (f)
        fclose(f);
    FX_CHECK_EQ(lines, 3);

    memset(&st2, 0, sizeof st2);
    st2.interactive = 1;
    demo_anim_init(&st2); /* played back from the file */
    FX_CHECK_EQ(st2.nflight, 3);
    FX_CHECK(!memcmp(st2.flight, st.flight, 3 * sizeof st.flight[0]));

    uint32_t *px = calloc(800 * 480, 4);
    fx_surface s;
    fx_surface_init(&s, px, 800, 480, 800 * 4, FX_FMT_XRGB8888);
    fx_ctx c;
    fx_ctx_init(&c, &s);
    st2.frame = 100;
    press(&st2, "g");
    FX_CHECK(st2.flying);
    int at_key[3] = {0, 0, 0}, moved = 0;
    fx_vec3 prev = st2.acam.eye;
    for (int f2 = 0; f2 <= 95; f2 += 5) {
        st2.frame = 100 + (uint32_t)f2;
        demo_anim_page(&c, &st2, DEMO_TAB_H + 8);
        for (int k = 0; k < 3; k++)
            if (f2 == 45 * k) {
                at_key[k] = eye_is(&st2, &st2.flight[k]);
                FX_CHECK_MSG(at_key[k], "frame %d: the camera is not on key %d", f2, k);
            }
        moved += memcmp(&prev, &st2.acam.eye, sizeof prev) != 0;
        prev = st2.acam.eye;
    }
    FX_CHECK(moved >= 10);
    FX_CHECK(!st2.flying); /* arrived */
    FX_CHECK(eye_is(&st2, &st2.flight[2]));
    /* the look-at point recorded is where the camera looks on arrival */
    FX_CHECK(st2.acam.n.x || st2.acam.n.y || st2.acam.n.z);
    press(&st2, "x");
    FX_CHECK_EQ(st2.nflight, 0);
    /* x clears the file too: a new flight recorded after it is the one a
     * fresh page loads (appended, its t = 0 key stopped the reload at the
     * old flight) */
    press(&st2, "fkfk");
    static demo_state st3;
    memset(&st3, 0, sizeof st3);
    st3.interactive = 1;
    demo_anim_init(&st3);
    FX_CHECK_EQ(st3.nflight, 2);
    FX_CHECK(!memcmp(st3.flight, st2.flight, 2 * sizeof st2.flight[0]));
    free(px);
    unlink(path);
    demo_anim_set_file(NULL);
}

/* The end of the chain in st's pose, in Q16.16 px. */
static void arm_end(const demo_state *st, int32_t x0, int32_t y0, fx16 *ex, fx16 *ey)
{
    fx_kin_chain ch;
    fx16 p[2 * (DEMO_ARM_LINKS + 1)];
    demo_arm_chain(x0, y0, &ch);
    FX_CHECK_EQ(fx_kin_forward(&ch, st->arm_theta, p), DEMO_ARM_LINKS + 1);
    *ex = p[2 * DEMO_ARM_LINKS], *ey = p[2 * DEMO_ARM_LINKS + 1];
}

static int64_t dist2(fx16 ax, fx16 ay, fx16 bx, fx16 by)
{
    int64_t dx = (int64_t)ax - bx, dy = (int64_t)ay - by;
    return dx * dx + dy * dy;
}

/* The Animation page's arm: it starts straight, far from its target, chases
 * it at no more than 3 px a frame, and once caught its end stays within a
 * pixel of the moving target, headless (frames 0..36, the golden's) and
 * from any frame on a display. */
FX_TEST(demo_arm_reaches_its_goal_directed_target)
{
    static demo_state st;
    memset(&st, 0, sizeof st);
    const int32_t x0 = 204, y0 = DEMO_TAB_H + 8 + 198;
    fx16 tx, ty, ex, ey;
    demo_arm_advance(&st, 36, x0, y0, &tx, &ty); /* headless: from frame 0 */
    FX_CHECK_EQ(st.arm_frame, 36u);
    FX_CHECK_EQ(st.arm_ntrail, 36);
    arm_end(&st, x0, y0, &ex, &ey);
    FX_CHECK_MSG(dist2(ex, ey, tx, ty) <= (int64_t)FX16_ONE * FX16_ONE, "end (%d, %d) target (%d, %d)", ex >> 16,
                 ey >> 16, tx >> 16, ty >> 16);

    memset(&st, 0, sizeof st);
    st.interactive = 1;
    demo_arm_advance(&st, 500, x0, y0, &tx, &ty); /* a display: straight at the frame it opens */
    FX_CHECK_EQ(st.arm_ntrail, 0);
    arm_end(&st, x0, y0, &ex, &ey);
    FX_CHECK(dist2(ex, ey, tx, ty) > (int64_t)20 * 20 * FX16_ONE * FX16_ONE);
    fx16 px = ex, py = ey;
    for (uint32_t f = 501; f <= 740; f++) {
        demo_arm_advance(&st, f, x0, y0, &tx, &ty);
        arm_end(&st, x0, y0, &ex, &ey);
        /* bounded speed: the aim steps 3 px, the end follows it to 1/64 */
        FX_CHECK_MSG(dist2(ex, ey, px, py) <= (int64_t)(3 * FX16_ONE + FX16_ONE / 16) * (3 * FX16_ONE + FX16_ONE / 16),
                     "frame %u: the end jumped", f);
        if (f >= 560) /* caught within 2 s, and kept */
            FX_CHECK_MSG(dist2(ex, ey, tx, ty) <= (int64_t)FX16_ONE * FX16_ONE, "frame %u: end (%d, %d) target (%d, %d)",
                         f, ex >> 16, ey >> 16, tx >> 16, ty >> 16);
        px = ex, py = ey;
    }
    FX_CHECK_EQ(st.arm_ntrail, DEMO_ARM_TRAIL);
}
