/* The golden model as a scoreboard, in C (docs/library.md): make a pipeline from a profile, submit
 * triangles one at a time, read back each triangle's setup record, fragments and cycle record, and
 * the buffers. Every call returns RASTERSIM_OK or an error code, with the reason in
 * rastersim_last_error(); no call aborts or throws. rastersim.hpp wraps it for C++; DPI-C and
 * Python bind to it. The model's own headers (model/pipeline.h) are richer but follow the model. */
#ifndef RASTERSIM_H
#define RASTERSIM_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define RASTERSIM_API_VERSION 1

enum {
  RASTERSIM_OK = 0,
  RASTERSIM_ERROR_ARGUMENT = 1, /* a null pointer, an index out of range, reading what was not made */
  RASTERSIM_ERROR_INPUT = 2     /* a bad profile or triangle (the message names the problem) */
};

enum { RASTERSIM_DRAWN = 0, RASTERSIM_DEGENERATE = 1, RASTERSIM_CULLED = 2, RASTERSIM_OFFSCREEN = 3, RASTERSIM_NO_CENTRE = 4 };

typedef struct rastersim_pipeline rastersim_pipeline;

/* A screen-space vertex as in a .tri file: x, y in pixels (y down), z in [0, 1] (0 near). */
typedef struct {
  double x, y, z;
  uint8_t r, g, b;
} rastersim_screen_vertex;

/* A snapped vertex, the words the setup unit takes: x, y in subpixels (s.S), z as uN. */
typedef struct {
  int32_t x, y;
  uint32_t z;
  uint8_t r, g, b;
} rastersim_snapped_vertex;

typedef struct {
  int64_t triangle; /* index in submission order */
  int32_t x, y;     /* pixel */
  uint32_t z;       /* depth entering the test, uN */
  uint8_t r, g, b;
  uint8_t pass;     /* the depth test passed (and wrote, with depth_write) */
  int64_t cycle;    /* the cycle the z-buffer accepted it (docs/cycle-model.md) */
} rastersim_fragment;

typedef struct {
  int64_t triangle;
  int32_t status; /* RASTERSIM_DRAWN, _DEGENERATE, _CULLED, _OFFSCREEN or _NO_CENTRE */
  int64_t setup_accept, setup_done, walker_load, walker_end; /* walker_*: -1 unless drawn */
  int64_t fragments, depth_pass;
  int64_t last_write; /* -1 without fragments */
} rastersim_triangle_record;

/* The setup record of a drawn triangle (docs/formats.md): edge k and colour channel c at [k], [c];
 * values as the registers hold them (two's complement, sign-extended to 64 bits). */
typedef struct {
  int32_t x0, y0, x1, y1;
  int64_t edge_start[3], edge_step_x[3], edge_step_y[3];
  int64_t span_quot[3], span_rem[3], span_step_quot[3], span_step_rem[3];
  int64_t depth_start, depth_step_x, depth_step_y;
  int64_t color_start[3], color_step_x[3], color_step_y[3];
  uint8_t flat_r, flat_g, flat_b;
  /* The planes along the left edges (docs/cycle-model.md), left-edge slot j at [j] (slot 0: the first
   * edge with edge_step_x > 0, slot 1: the second; a slot without an edge has start and step_y):
   * the plane at the slot edge's span start on the first row, start - span_quot * step_x, and its
   * change per row without the DDA's carry, step_y - span_step_quot * step_x, modulo the plane
   * register's width; colours zero without Gouraud shading. */
  int64_t left_depth_start[2], left_depth_step[2];
  int64_t left_color_start[2][3], left_color_step[2][3];
} rastersim_setup_record;

/* The release and the commit the library was built from, e.g. "0.1.0 (g1234abc)". */
const char* rastersim_version(void);
/* Why the last failing call on this thread failed ("" if none has). */
const char* rastersim_last_error(void);

/* A pipeline for one frame at the profile's settings: JSON text as a profile file holds it (keys
 * absent keep their defaults; NULL or "" is the default profile). */
int rastersim_create(const char* profile_json, rastersim_pipeline** pipeline);
/* The same from profile fields: keys[i] set to values[i] as the command line's flags take them
 * ("width" "64", "traversal" "bbox", "depth_clear" "max"); the others keep their defaults. */
int rastersim_create_from_fields(const char* const keys[], const char* const values[], size_t count,
                                 rastersim_pipeline** pipeline);
void rastersim_destroy(rastersim_pipeline* pipeline);
/* Starts a new frame: cleared buffers, cycle 0, no triangles. */
int rastersim_reset(rastersim_pipeline* pipeline);

int rastersim_width(const rastersim_pipeline* pipeline, int32_t* width);
int rastersim_height(const rastersim_pipeline* pipeline, int32_t* height);
/* The profile with every key resolved, as JSON text (valid until the next call on the pipeline). */
int rastersim_profile_json(const rastersim_pipeline* pipeline, const char** json);

/* Runs one triangle through setup, walker, Z adder and z-buffer; *triangle (may be NULL) gets its
 * index. A screen triangle is checked (finite, z in [0, 1], inside the guard band) and snapped. */
int rastersim_submit_screen(rastersim_pipeline* pipeline, const rastersim_screen_vertex vertices[3],
                            int64_t* triangle);
int rastersim_submit_snapped(rastersim_pipeline* pipeline, const rastersim_snapped_vertex vertices[3],
                             int64_t* triangle);

int rastersim_triangle_count(const rastersim_pipeline* pipeline, int64_t* count);
int rastersim_read_triangle(const rastersim_pipeline* pipeline, int64_t triangle,
                              rastersim_triangle_record* record);
/* Only for a drawn triangle (others have no record: RASTERSIM_ERROR_ARGUMENT). */
int rastersim_read_setup(const rastersim_pipeline* pipeline, int64_t triangle, rastersim_setup_record* record);
int rastersim_fragment_count(const rastersim_pipeline* pipeline, int64_t triangle, int64_t* count);
/* Fragment k (in the order the walker emitted them) of a triangle. */
int rastersim_read_fragment(const rastersim_pipeline* pipeline, int64_t triangle, int64_t k, rastersim_fragment* fragment);

/* The frame's cycle count so far: the first cycle after every unit's last busy cycle. */
int rastersim_frame_cycles(rastersim_pipeline* pipeline, int64_t* cycles);
/* The depth and colour buffer words of a pixel (colour as 0x00RRGGBB). */
int rastersim_read_depth(const rastersim_pipeline* pipeline, int32_t x, int32_t y, uint32_t* depth);
int rastersim_read_color(const rastersim_pipeline* pipeline, int32_t x, int32_t y, uint32_t* rgb);

/* The same with the types of DPI-C (api/rastersim_dpi.sv imports them): scalars instead of structs,
 * colours as 0x00RRGGBB, `long long` for SystemVerilog's longint, `void*` for its chandle. Every
 * import has a C name of its own (rastersim_dpi_*), so that a simulator's generated DPI header and
 * this one can be included in one file. */
const char* rastersim_dpi_version(void);
const char* rastersim_dpi_last_error(void);
int rastersim_dpi_create(const char* profile_json, void** pipeline);
void rastersim_dpi_destroy(void* pipeline);
int rastersim_dpi_reset(void* pipeline);
int rastersim_dpi_width(void* pipeline, int* width);
int rastersim_dpi_height(void* pipeline, int* height);
int rastersim_dpi_submit_screen(void* pipeline, double x0, double y0, double z0, unsigned rgb0, double x1,
                                double y1, double z1, unsigned rgb1, double x2, double y2, double z2,
                                unsigned rgb2, long long* triangle);
int rastersim_dpi_submit_snapped(void* pipeline, int x0, int y0, unsigned z0, unsigned rgb0, int x1, int y1,
                                 unsigned z1, unsigned rgb1, int x2, int y2, unsigned z2, unsigned rgb2,
                                 long long* triangle);
int rastersim_dpi_read_triangle(void* pipeline, long long triangle, int* status, long long* setup_accept,
                                long long* setup_done, long long* walker_load, long long* walker_end,
                                long long* fragments, long long* last_write);
int rastersim_dpi_read_fragment(void* pipeline, long long triangle, long long k, int* x, int* y, unsigned* z,
                                unsigned* rgb, int* pass, long long* cycle);
int rastersim_dpi_frame_cycles(void* pipeline, long long* cycles);
int rastersim_dpi_read_buffers(void* pipeline, int x, int y, unsigned* depth, unsigned* rgb);

#ifdef __cplusplus
}
#endif

#endif /* RASTERSIM_H */
