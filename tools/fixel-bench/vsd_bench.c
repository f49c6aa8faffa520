/* SPDX-License-Identifier: MIT */
/* TABLE 6: the visible-surface methods of issue #23 on the same scene
 * (fixel/vsd.h: the course scene plus random triangles, 400x300) at two
 * scene sizes, so the growth of each method's cost shows: per method the
 * time of one frame at each size, the growth factor between them, and the
 * time relative to the z-buffer at the larger size. Every frame is also
 * checked against the z-buffer (pixels that differ; the A-buffer's column
 * counts its blended edge pixels instead). Trials interleave the methods,
 * the median is shown. The octree method, which draws a voxel solid rather
 * than polygons, gets its own row at 16^3 and 64^3 voxels. */
#include "bench.h"

#include <fixel/vsd.h>
#include <fixel/surface.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define VW 400
#define VH 300
static const int32_t SIZES[2] = {20, 200}; /* random triangles on top of the 6 polygons */

typedef struct vscene {
    fx_vsd_scene s;
    fx_vsd_vertex v[4096];
    fx_vsd_edge e[4096];
    fx_vsd_poly p[1024];
} vscene;

static double med_ms[FX_VSD_METHODS][2];
static int32_t differ[FX_VSD_METHODS][2];
static int32_t npolys[2];
static double oct_ms[2];
static int32_t oct_nodes[2];
static int vsd_ran;

static int frame(const fx_vsd_scene *s, int m, int32_t *ids, void *work, size_t bytes,
                 const fx_surface *surf, int32_t *edges)
{
    if (m == FX_VSD_ABUFFER)
        return fx_vsd_abuffer(s, surf, 0, 0, work, bytes, edges);
    return fx_vsd_render(s, (fx_vsd_method)m, ids, work, bytes, NULL, 0, NULL);
}

void vsd_bench_run(int trials, double min_s, int quiet)
{
    static uint32_t px[VW * VH];
    fx_surface surf;
    fx_surface_init(&surf, px, VW, VH, VW * 4, FX_FMT_XRGB8888);
    int32_t *ids = malloc(sizeof(int32_t) * VW * VH), *ref = malloc(sizeof(int32_t) * VW * VH);
    if (!quiet)
        fprintf(stderr, "vsd ");
    for (int z = 0; z < 2; z++) {
        vscene *sc = calloc(1, sizeof *sc);
        fx_vsd_init(&sc->s, VW, VH, sc->v, 4096, sc->e, 4096, sc->p, 1024);
        if (fx_vsd_demo_scene(&sc->s, SIZES[z]) < 0)
            abort();
        npolys[z] = sc->s.npoly;
        size_t bytes[FX_VSD_METHODS];
        void *work[FX_VSD_METHODS];
        int reps[FX_VSD_METHODS];
        double vals[FX_VSD_METHODS][64];
        fx_vsd_render(&sc->s, FX_VSD_ZBUFFER, ref, NULL, 0, NULL, 0, NULL);
        for (int m = 0; m < FX_VSD_METHODS; m++) {
            bytes[m] = fx_vsd_work_bytes(&sc->s, (fx_vsd_method)m,
                                         m == FX_VSD_ABUFFER ? 6 * VW * VH : 64 * sc->s.npoly);
            work[m] = aligned_alloc(64, (bytes[m] + 64) & ~(size_t)63);
            int32_t edges = 0;
            if (frame(&sc->s, m, ids, work[m], bytes[m], &surf, &edges) < 0) {
                fprintf(stderr, "fixel-bench: vsd %s failed\n", fx_vsd_method_name((fx_vsd_method)m));
                abort();
            }
            differ[m][z] = edges;
            if (m != FX_VSD_ABUFFER)
                for (int32_t i = 0; i < VW * VH; i++)
                    differ[m][z] += ids[i] != ref[i];
            double t0 = bench_secs();
            int k = 0;
            do
                frame(&sc->s, m, ids, work[m], bytes[m], &surf, &edges), k++;
            while (bench_secs() - t0 < min_s / 4);
            double per = (bench_secs() - t0) / k;
            reps[m] = per > 0 ? (int)(min_s / per) + 1 : 1;
        }
        int nt = trials > 64 ? 64 : trials;
        for (int t = 0; t < nt; t++) {
            for (int q = 0; q < FX_VSD_METHODS; q++) {
                int m = (q + t) % FX_VSD_METHODS;
                int32_t edges;
                double t0 = bench_secs();
                for (int k = 0; k < reps[m]; k++)
                    frame(&sc->s, m, ids, work[m], bytes[m], &surf, &edges);
                vals[m][t] = (bench_secs() - t0) / reps[m];
            }
            if (!quiet)
                fprintf(stderr, ".");
        }
        for (int m = 0; m < FX_VSD_METHODS; m++) {
            qsort(vals[m], (size_t)nt, sizeof vals[m][0], bench_cmp_double);
            med_ms[m][z] = 1e3 * (nt & 1 ? vals[m][nt / 2] : (vals[m][nt / 2 - 1] + vals[m][nt / 2]) / 2);
            free(work[m]);
        }
        free(sc);
    }
    /* the octree method on the voxel solid, 16^3 and 64^3 voxels, both 256 px wide */
    for (int z = 0; z < 2; z++) {
        int32_t k = z ? 6 : 4, n = 1 << k, sc = 256 / n;
        uint8_t *vox = malloc((size_t)n * n * n);
        int32_t cap = ((1 << (3 * k + 3)) - 1) / 7;
        fx_vsd_onode *nodes = malloc(sizeof *nodes * (size_t)cap);
        fx_vsd_demo_solid(vox, k);
        fx_vsd_octree o;
        if (fx_vsd_octree_build(&o, nodes, cap, vox, k) < 0)
            abort();
        oct_nodes[z] = o.nnode;
        double t0 = bench_secs();
        int reps = 0;
        do
            fx_vsd_octree_render(&o, sc, ids, 256, 256), reps++;
        while (bench_secs() - t0 < min_s / 4);
        reps = (int)(min_s / ((bench_secs() - t0) / reps)) + 1;
        double vals[64];
        int nt = trials > 64 ? 64 : trials;
        for (int t = 0; t < nt; t++) {
            t0 = bench_secs();
            for (int r = 0; r < reps; r++)
                fx_vsd_octree_render(&o, sc, ids, 256, 256);
            vals[t] = (bench_secs() - t0) / reps;
        }
        qsort(vals, (size_t)nt, sizeof vals[0], bench_cmp_double);
        oct_ms[z] = 1e3 * (nt & 1 ? vals[nt / 2] : (vals[nt / 2 - 1] + vals[nt / 2]) / 2);
        free(vox);
        free(nodes);
    }
    free(ids);
    free(ref);
    vsd_ran = 1;
    if (!quiet)
        fprintf(stderr, "\n");
}

void vsd_bench_print(FILE *o)
{
    if (!vsd_ran)
        return;
    fprintf(o, "\nTABLE 6: visible-surface methods, one %dx%d frame (fixel/vsd.h course scene + random triangles)\n",
            VW, VH);
    fprintf(o, "%-10s %12s %12s %8s %10s %14s\n", "method", "", "", "growth", "x zbuffer", "px != zbuffer");
    char h0[24], h1[24];
    snprintf(h0, sizeof h0, "%d polys ms", npolys[0]);
    snprintf(h1, sizeof h1, "%d polys ms", npolys[1]);
    fprintf(o, "%-10s %12s %12s %8s %10s %14s\n", "", h0, h1, "", "(large)", "(small/large)");
    for (int m = 0; m < FX_VSD_METHODS; m++) {
        char d[32];
        if (m == FX_VSD_ABUFFER)
            snprintf(d, sizeof d, "%d/%d edge", differ[m][0], differ[m][1]);
        else
            snprintf(d, sizeof d, "%d/%d", differ[m][0], differ[m][1]);
        fprintf(o, "%-10s %12.3f %12.3f %7.2fx %9.2fx %14s\n", fx_vsd_method_name((fx_vsd_method)m),
                med_ms[m][0], med_ms[m][1], med_ms[m][0] > 0 ? med_ms[m][1] / med_ms[m][0] : 0,
                med_ms[0][1] > 0 ? med_ms[m][1] / med_ms[0][1] : 0, d);
    }
    fprintf(o, "%-10s %12.3f %12.3f %7.2fx %10s %14s\n", "octree", oct_ms[0], oct_ms[1],
            oct_ms[0] > 0 ? oct_ms[1] / oct_ms[0] : 0, "-", "(voxels)");
    fprintf(o, "  octree: the voxel solid of fixel/vsd.h, 16^3 (%d nodes) and 64^3 (%d nodes), 256x256 px\n",
            oct_nodes[0], oct_nodes[1]);
}
