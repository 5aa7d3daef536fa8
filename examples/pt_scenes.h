/* pt_scenes.h - the fovpt benchmark and example scenes, written in code (no downloads).
   Hosted helper (malloc), not part of the library. Include fovpt.h first.

     PT_SCENE_CORNELL   Cornell box: 5 Lambert walls (red / green sides), a quad light,
                        two boxes, a Phong sphere and a mirror sphere
     PT_SCENE_MESH      a procedural height-field terrain of 2 x 224 x 224 = 100 352
                        triangles under a sky and a sphere sun
     PT_SCENE_CUBES     441 axis-aligned cubes on a 21 x 21 grid (the multi-object scene of
                        Axblad 2020, Fig. 3.3) on a floor, lit by a quad light and the sky
     PT_SCENE_MIRRORS   the mirror room of Axblad 2020, Fig. 3.4: six slightly emissive
                        mirror walls around a few objects (every path reaches the bounce
                        limit)
     PT_SCENE_INTERIOR  a room with four lights (three ceiling quads, one sphere lamp),
                        furniture boxes, a glass sphere and a Phong sphere
   Axblad 2020: T. Axblad, "Impact of Foveated Rendering on Path Tracing Frame Rate in
   Head-Mounted VR Displays", master's thesis, KTH Royal Institute of Technology, 2020.

   pt_scene_make(&s, id) fills s (shapes, meshes, materials, camera) and builds the scene;
   pt_scene_free(&s). Returns 0 on success. */
#ifndef PT_SCENES_H
#define PT_SCENES_H
#include <math.h>
#include <stdlib.h>
#include <string.h>

enum { PT_SCENE_CORNELL, PT_SCENE_MESH, PT_SCENE_CUBES, PT_SCENE_MIRRORS, PT_SCENE_INTERIOR, PT_SCENE_NUM };
static const char *const pt_scene_names[PT_SCENE_NUM] = { "cornell", "mesh100k", "cubes441", "mirrors", "interior" };

typedef struct pt_scene {
    fovpt_shape *shapes;
    uint32_t num_shapes, cap_shapes;
    fovpt_material mats[16];
    uint32_t num_mats;
    fovpt_mesh mesh;
    float *pos;
    uint32_t *idx;
    fovpt_scene_desc desc;
    fovpt_scene scene;
    void *mem;
    fovpt_camera cam;   /* pose and field of view; the caller sets width and height */
} pt_scene;

static uint32_t pt_mat(pt_scene *s, uint32_t type, float r, float g, float b)
{
    fovpt_material *m = &s->mats[s->num_mats];
    fovpt_material_init(m);
    m->type = type;
    m->albedo[0] = r; m->albedo[1] = g; m->albedo[2] = b;
    return s->num_mats++;
}
static uint32_t pt_light(pt_scene *s, float r, float g, float b)
{
    uint32_t i = pt_mat(s, FOVPT_MAT_LAMBERT, 0.0f, 0.0f, 0.0f);
    s->mats[i].emission[0] = r; s->mats[i].emission[1] = g; s->mats[i].emission[2] = b;
    return i;
}
static fovpt_shape *pt_add(pt_scene *s)
{
    if (s->num_shapes == s->cap_shapes) {
        s->cap_shapes = s->cap_shapes ? 2u * s->cap_shapes : 64u;
        s->shapes = (fovpt_shape *)realloc(s->shapes, sizeof(fovpt_shape) * s->cap_shapes);
    }
    return &s->shapes[s->num_shapes++];
}
static void pt_quad(pt_scene *s, float x, float y, float z, float ux, float uy, float uz, float vx, float vy, float vz,
                    uint32_t m)
{
    float c[3], u[3], v[3];
    c[0] = x; c[1] = y; c[2] = z; u[0] = ux; u[1] = uy; u[2] = uz; v[0] = vx; v[1] = vy; v[2] = vz;
    fovpt_shape_quad(pt_add(s), c, u, v, m);
}
static void pt_box(pt_scene *s, float x0, float y0, float z0, float x1, float y1, float z1, uint32_t m)
{
    float lo[3], hi[3];
    lo[0] = x0; lo[1] = y0; lo[2] = z0; hi[0] = x1; hi[1] = y1; hi[2] = z1;
    fovpt_shape_box(pt_add(s), lo, hi, m);
}
static void pt_look(pt_scene *s, float px, float py, float pz, float tx, float ty, float tz, float fov)
{
    s->cam.pos[0] = px; s->cam.pos[1] = py; s->cam.pos[2] = pz;
    s->cam.target[0] = tx; s->cam.target[1] = ty; s->cam.target[2] = tz;
    s->cam.fov_y_deg = fov;
}
/* an open box room [-w, w] x [0, h] x [-d, d], walls facing inwards */
static void pt_room(pt_scene *s, float w, float h, float d, uint32_t floor_m, uint32_t wall_m, uint32_t left_m,
                    uint32_t right_m, uint32_t ceil_m, int front)
{
    pt_quad(s, -w, 0, -d, 0, 0, 2 * d, 2 * w, 0, 0, floor_m);         /* floor, normal +y */
    pt_quad(s, -w, h, -d, 2 * w, 0, 0, 0, 0, 2 * d, ceil_m);          /* ceiling, normal -y */
    pt_quad(s, -w, 0, d, 0, h, 0, 2 * w, 0, 0, wall_m);               /* back wall */
    pt_quad(s, -w, 0, -d, 0, h, 0, 0, 0, 2 * d, left_m);              /* left */
    pt_quad(s, w, 0, -d, 0, 0, 2 * d, 0, h, 0, right_m);              /* right */
    if (front) pt_quad(s, -w, 0, -d, 2 * w, 0, 0, 0, h, 0, wall_m);   /* front (behind the camera) */
}

static int pt_scene_make(pt_scene *s, int id)
{
    size_t bytes = 0;
    memset(s, 0, sizeof *s);
    fovpt_camera_init(&s->cam, 1, 1);
    fovpt_scene_desc_init(&s->desc);
    switch (id) {
    case PT_SCENE_CORNELL: {
        uint32_t white = pt_mat(s, FOVPT_MAT_LAMBERT, 0.73f, 0.73f, 0.73f);
        uint32_t red = pt_mat(s, FOVPT_MAT_LAMBERT, 0.65f, 0.05f, 0.05f);
        uint32_t green = pt_mat(s, FOVPT_MAT_LAMBERT, 0.12f, 0.45f, 0.15f);
        uint32_t light = pt_light(s, 15.0f, 15.0f, 15.0f);
        uint32_t phong = pt_mat(s, FOVPT_MAT_PHONG, 0.2f, 0.3f, 0.6f);
        uint32_t mirror = pt_mat(s, FOVPT_MAT_MIRROR, 0.9f, 0.9f, 0.9f);
        s->mats[phong].specular[0] = s->mats[phong].specular[1] = s->mats[phong].specular[2] = 0.3f;
        s->mats[phong].exponent = 40.0f;
        pt_room(s, 1.0f, 2.0f, 1.0f, white, white, red, green, white, 0);
        pt_quad(s, -0.25f, 1.999f, -0.25f, 0.5f, 0, 0, 0, 0, 0.5f, light);
        pt_box(s, -0.7f, 0.0f, -0.1f, -0.15f, 1.2f, 0.5f, white);
        pt_box(s, 0.15f, 0.0f, -0.6f, 0.7f, 0.6f, -0.05f, white);
        fovpt_shape_sphere(pt_add(s), 0.42f, 0.85f, -0.32f, 0.25f, phong);
        fovpt_shape_sphere(pt_add(s), -0.45f, 1.45f, 0.2f, 0.25f, mirror);
        pt_look(s, 0.0f, 1.0f, -3.4f, 0.0f, 1.0f, 0.0f, 40.0f);
        break;
    }
    case PT_SCENE_MESH: {
        uint32_t n = 224, i, j, k = 0;
        uint32_t ground = pt_mat(s, FOVPT_MAT_LAMBERT, 0.55f, 0.5f, 0.4f);
        uint32_t sun = pt_light(s, 60.0f, 55.0f, 45.0f);
        s->pos = (float *)malloc(sizeof(float) * 3u * (n + 1u) * (n + 1u));
        s->idx = (uint32_t *)malloc(sizeof(uint32_t) * 6u * n * n);
        for (j = 0; j <= n; ++j)
            for (i = 0; i <= n; ++i) {
                float x = -10.0f + 20.0f * (float)i / (float)n, z = -10.0f + 20.0f * (float)j / (float)n;
                float h = 0.6f * sinf(0.9f * x) * cosf(0.7f * z) + 0.25f * sinf(2.7f * x + 1.3f * z) + 0.08f * sinf(9.0f * x) * sinf(8.0f * z);
                float *p = s->pos + 3u * (j * (n + 1u) + i);
                p[0] = x; p[1] = h; p[2] = z;
            }
        for (j = 0; j < n; ++j)
            for (i = 0; i < n; ++i) {
                uint32_t a = j * (n + 1u) + i, b = a + 1u, c = a + n + 1u, d = c + 1u;
                s->idx[k++] = a; s->idx[k++] = c; s->idx[k++] = b;
                s->idx[k++] = b; s->idx[k++] = c; s->idx[k++] = d;
            }
        s->mesh.positions = s->pos; s->mesh.num_vertices = (n + 1u) * (n + 1u);
        s->mesh.indices = s->idx; s->mesh.num_triangles = 2u * n * n; s->mesh.material = ground;
        s->desc.meshes = &s->mesh; s->desc.num_meshes = 1;
        fovpt_shape_sphere(pt_add(s), 6.0f, 8.0f, 4.0f, 1.0f, sun);
        s->desc.background[0] = 0.35f; s->desc.background[1] = 0.45f; s->desc.background[2] = 0.6f;
        pt_look(s, 0.0f, 2.5f, -9.0f, 0.0f, 0.0f, 0.0f, 55.0f);
        break;
    }
    case PT_SCENE_CUBES: {
        uint32_t floor_m = pt_mat(s, FOVPT_MAT_LAMBERT, 0.6f, 0.6f, 0.6f), i, j;
        uint32_t cm[3], light = pt_light(s, 8.0f, 8.0f, 8.0f);
        float p[3] = { 0.0f, 0.0f, 0.0f }, nn[3] = { 0.0f, 1.0f, 0.0f };
        cm[0] = pt_mat(s, FOVPT_MAT_LAMBERT, 0.7f, 0.3f, 0.2f);
        cm[1] = pt_mat(s, FOVPT_MAT_LAMBERT, 0.2f, 0.5f, 0.7f);
        cm[2] = pt_mat(s, FOVPT_MAT_PHONG, 0.5f, 0.5f, 0.2f);
        s->mats[cm[2]].specular[0] = s->mats[cm[2]].specular[1] = s->mats[cm[2]].specular[2] = 0.3f;
        fovpt_shape_plane(pt_add(s), p, nn, floor_m);
        for (j = 0; j < 21; ++j)
            for (i = 0; i < 21; ++i) {
                float x = -10.0f + (float)i, z = -10.0f + (float)j, h = 0.3f + 0.5f * (float)((i * 7u + j * 3u) % 5u) / 4.0f;
                pt_box(s, x - 0.3f, 0.0f, z - 0.3f, x + 0.3f, h, z + 0.3f, cm[(i + j) % 3u]);
            }
        pt_quad(s, -3.0f, 8.0f, -3.0f, 6.0f, 0, 0, 0, 0, 6.0f, light);
        s->desc.background[0] = 0.25f; s->desc.background[1] = 0.3f; s->desc.background[2] = 0.4f;
        pt_look(s, 0.0f, 6.0f, -15.0f, 0.0f, 0.0f, 0.0f, 50.0f);
        break;
    }
    case PT_SCENE_MIRRORS: {
        uint32_t mir = pt_mat(s, FOVPT_MAT_MIRROR, 0.85f, 0.85f, 0.9f);
        uint32_t red = pt_mat(s, FOVPT_MAT_LAMBERT, 0.7f, 0.2f, 0.2f);
        uint32_t glass = pt_mat(s, FOVPT_MAT_DIELECTRIC, 1.0f, 1.0f, 1.0f);
        s->mats[mir].emission[0] = s->mats[mir].emission[1] = s->mats[mir].emission[2] = 0.05f; /* "slightly illuminating" */
        pt_room(s, 2.0f, 3.0f, 3.0f, mir, mir, mir, mir, mir, 1);
        fovpt_shape_sphere(pt_add(s), -0.6f, 0.7f, 0.5f, 0.7f, red);
        fovpt_shape_sphere(pt_add(s), 0.8f, 0.5f, -0.3f, 0.5f, glass);
        pt_box(s, 0.9f, 0.0f, 1.0f, 1.5f, 1.6f, 1.6f, red);
        pt_look(s, 0.0f, 1.4f, -2.6f, 0.0f, 0.9f, 0.5f, 60.0f);
        break;
    }
    default: { /* interior */
        uint32_t wall = pt_mat(s, FOVPT_MAT_LAMBERT, 0.75f, 0.72f, 0.68f);
        uint32_t wood = pt_mat(s, FOVPT_MAT_PHONG, 0.45f, 0.3f, 0.18f);
        uint32_t blue = pt_mat(s, FOVPT_MAT_LAMBERT, 0.2f, 0.3f, 0.6f);
        uint32_t glass = pt_mat(s, FOVPT_MAT_DIELECTRIC, 0.95f, 0.97f, 1.0f);
        uint32_t l1 = pt_light(s, 6.0f, 5.5f, 5.0f), l2 = pt_light(s, 3.0f, 4.0f, 6.0f), lamp = pt_light(s, 30.0f, 22.0f, 12.0f);
        uint32_t i;
        s->mats[wood].specular[0] = s->mats[wood].specular[1] = s->mats[wood].specular[2] = 0.2f;
        s->mats[wood].exponent = 25.0f;
        pt_room(s, 4.0f, 3.0f, 5.0f, wood, wall, wall, blue, wall, 1);
        for (i = 0; i < 3; ++i) pt_quad(s, -3.0f + 2.5f * (float)i, 2.999f, 0.5f, 1.0f, 0, 0, 0, 0, 1.0f, i == 1 ? l2 : l1);
        fovpt_shape_sphere(pt_add(s), 2.8f, 1.7f, 3.5f, 0.15f, lamp);
        pt_box(s, -1.5f, 0.0f, 1.0f, 0.5f, 0.8f, 2.2f, wood);           /* table */
        pt_box(s, -3.8f, 0.0f, 2.0f, -2.8f, 2.2f, 4.8f, wall);          /* cupboard */
        pt_box(s, 1.6f, 0.0f, 2.5f, 3.4f, 0.5f, 4.5f, blue);            /* bed */
        pt_box(s, 2.6f, 0.0f, 3.3f, 3.0f, 1.5f, 3.7f, wood);            /* lamp stand */
        fovpt_shape_sphere(pt_add(s), -0.9f, 1.1f, 1.6f, 0.3f, glass);
        fovpt_shape_sphere(pt_add(s), 0.1f, 1.05f, 1.8f, 0.25f, wood);
        pt_look(s, 0.0f, 1.6f, -4.5f, 0.0f, 1.0f, 2.0f, 60.0f);
        break;
    }
    }
    s->desc.shapes = s->shapes; s->desc.num_shapes = s->num_shapes;
    s->desc.materials = s->mats; s->desc.num_materials = s->num_mats;
    if (fovpt_scene_size(&s->desc, &bytes) != FOV_OK) return 1;
    s->mem = malloc(bytes + 16u);
    if (!s->mem || fovpt_scene_build(&s->scene, &s->desc, s->mem, bytes) != FOV_OK) return 2;
    return 0;
}

static void pt_scene_free(pt_scene *s)
{
    free(s->shapes); free(s->pos); free(s->idx); free(s->mem);
    memset(s, 0, sizeof *s);
}
#endif
