/* tinybvh_row.cpp - the optional tinybvh row of bench_pt's ray throughput (C++ wrapper).

   Compiled only when the user points the bench at a local copy of tinybvh's single header
   (never committed): make bench-pt TINYBVH=/path/to/tiny_bvh.h. It builds tinybvh's best
   CPU layout on the triangles bench_pt gives it: BVH8_CPU (8-wide nodes, AVX2 + FMA,
   built with BuildHQ, the spatial-split build tinybvh's speed test uses for this layout)
   when the compiler targets AVX2 and FMA; otherwise BVH4_CPU (SSE), otherwise the plain BVH.
   The functions below are all bench_pt sees (extern "C"). */
#include <stdint.h>
#include <stddef.h>
#include <math.h>

#define TINYBVH_IMPLEMENTATION
#include TINYBVH_HEADER

#if defined(__AVX2__) && defined(__FMA__)
typedef tinybvh::BVH8_CPU tbvh_type;
static const char tbvh_layout_name[] = "BVH8_CPU AVX2 BuildHQ";
#elif defined(__AVX__)
typedef tinybvh::BVH4_CPU tbvh_type;
static const char tbvh_layout_name[] = "BVH4_CPU BuildHQ";
#else
typedef tinybvh::BVH tbvh_type;
static const char tbvh_layout_name[] = "BVH BuildHQ";
#endif

struct tbvh_handle {
    tinybvh::bvhvec4 *verts;
    tbvh_type *bvh;
};

extern "C" const char *tbvh_layout(void) { return tbvh_layout_name; }

/* tri: 9 floats per triangle (v0, v1, v2); returns NULL on failure */
extern "C" void *tbvh_build(const float *tri, uint32_t ntri, size_t *bytes)
{
    tbvh_handle *h = new tbvh_handle;
    h->verts = new tinybvh::bvhvec4[3u * (size_t)ntri];
    for (size_t i = 0; i < 3u * (size_t)ntri; ++i)
        h->verts[i] = tinybvh::bvhvec4(tri[3 * i], tri[3 * i + 1], tri[3 * i + 2], 0.0f);
    h->bvh = new tbvh_type();
    h->bvh->BuildHQ(h->verts, ntri);
#if defined(__AVX__)
    *bytes = (size_t)h->bvh->usedBlocks * 64u; /* nodes and triangles (64-byte blocks), what traversal reads */
#else
    *bytes = (size_t)h->bvh->usedNodes * sizeof(tinybvh::BVH::BVHNode) + 4u * (size_t)ntri;
#endif
    return h;
}

/* closest hit t along dir (any length), or -1 for a miss */
extern "C" void tbvh_trace(void *hp, const float *org, const float *dir, size_t n, float *t_out)
{
    tbvh_handle *h = (tbvh_handle *)hp;
    for (size_t i = 0; i < n; ++i) {
        const float *o = org + 3 * i, *d = dir + 3 * i;
        tinybvh::Ray r(tinybvh::bvhvec3(o[0], o[1], o[2]), tinybvh::bvhvec3(d[0], d[1], d[2]));
        h->bvh->Intersect(r);
        if (r.hit.t < BVH_FAR) {
            float l = sqrtf(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
            t_out[i] = r.hit.t / l; /* tinybvh normalises the direction */
        } else {
            t_out[i] = -1.0f;
        }
    }
}

extern "C" void tbvh_free(void *hp)
{
    tbvh_handle *h = (tbvh_handle *)hp;
    if (!h) return;
    delete h->bvh;
    delete[] h->verts;
    delete h;
}
