/* SPDX-License-Identifier: MIT */
/* libFuzzer target: the Wavefront OBJ parser, then the 3D pipeline drawing
 * whatever it accepted. The first byte picks shading, culling, polygon mode
 * and visibility; the rest is the OBJ text. The size pass and the parse pass
 * must agree, every index must name a vertex, and drawing any accepted mesh
 * (huge, degenerate, behind the eye) must stay inside a guarded surface. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "fixel/mesh.h"
#include "fixel/render3d.h"
#include "guard.h"

/* Bigger meshes are legal but only slow the fuzzer down. */
#define MAX_VERTS 4096
#define MAX_TRIS 8192

static const fx_format formats[] = {FX_FMT_XRGB8888, FX_FMT_RGB565, FX_FMT_RGB888, FX_FMT_GRAY8};

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 1)
        return 0;
    uint8_t mode = data[0];
    data++, size--;
    /* an exact-size heap copy, so ASan catches a read one past the end */
    char *text = malloc(size ? size : 1);
    memcpy(text, data, size);

    int32_t nv = -1, nt = -1;
    fx_obj_error err;
    memset(&err, 0, sizeof err);
    int rc = fx_mesh_obj_size(text, size, &nv, &nt, &err);
    if (rc < 0) {
        if (memchr(err.msg, 0, sizeof err.msg) == NULL || err.msg[0] == 0)
            abort(); /* a rejection must come with a message */
        free(text);
        return 0;
    }
    if (nv < 0 || nt < 0)
        abort();
    if (nv > MAX_VERTS || nt > MAX_TRIS) {
        free(text);
        return 0;
    }
    fx_mesh m = {0};
    m.pos = malloc(sizeof(fx_vec3) * (size_t)(nv ? nv : 1));
    m.nrm = (mode & 0x80) ? NULL : malloc(sizeof(fx_vec3) * (size_t)(nv ? nv : 1));
    m.tri = malloc(sizeof(uint32_t) * 3 * (size_t)(nt ? nt : 1));
    m.cap_verts = nv;
    m.cap_tris = nt;
    rc = fx_mesh_obj_parse(&m, text, size, &err);
    if (rc < 0)
        abort(); /* the size pass accepted this text */
    if (m.nverts != nv || m.ntris != nt)
        abort();
    for (int32_t i = 0; i < 3 * m.ntris; i++)
        if (m.tri[i] >= (uint32_t)m.nverts)
            abort();

    guarded g;
    if (guarded_make(&g, 37, 29, formats[(mode >> 5) & 3], mode & 1) == 0) {
        fx_mat4 ms[4], ps[2];
        fx3d r;
        fx3d_init(&r, &g.s, ms, 4, ps, 2);
        if (mode & 2)
            fx3d_perspective(&r, FX_ANGLE_90, FX16_ONE, FX16_ONE / 4, 40 * FX16_ONE);
        else
            fx3d_ortho(&r, -4 * FX16_ONE, 4 * FX16_ONE, -3 * FX16_ONE, 3 * FX16_ONE, FX16_ONE / 4,
                       40 * FX16_ONE);
        fx_mat4 t;
        fx_mat4_identity(&t);
        fx_mat4_translate(&t, 0, 0, -5 * FX16_ONE);
        fx_mat_stack_mult(&r.model, &t);
        r.shading = (fx3d_shading)((mode >> 2) % 3);
        r.cull = (fx3d_cull)((mode >> 3) % 3);
        r.polymode = (fx3d_polymode)((mode >> 4) % 3);
        size_t zb = fx3d_depth_bytes(&g.s, 16);
        void *depth = NULL;
        if (mode & 0x40) {
            depth = malloc(zb);
            fx3d_set_depth(&r, depth, 16);
        }
        fx3d_draw(&r, &m);
        free(depth);
        guarded_free(&g);
    }
    free(m.pos);
    free(m.nrm);
    free(m.tri);
    free(text);
    return 0;
}
