/* The golden model as a scoreboard, from C (docs/library.md). Reads a profile (JSON) and a .tri
 * file, submits every triangle, and writes what a testbench would compare against its DUT: each
 * triangle's cycle record and setup record, every fragment (the CSV of `rastersim render
 * --fragments`), and the final buffers. Build it against an installed rastersim:
 *   cmake -S examples/scoreboard -B sb -DCMAKE_PREFIX_PATH=PREFIX && cmake --build sb
 * or: cc scoreboard.c $(pkg-config --cflags --libs rastersim)
 * Usage: scoreboard PROFILE.json TRIANGLES.tri FRAGMENTS.csv BUFFERS.txt */
#include <rastersim/rastersim.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static char* read_file(const char* path) {
  FILE* f = fopen(path, "rb");
  if (!f) return NULL;
  size_t size = 0, capacity = 4096;
  char* text = malloc(capacity);
  size_t n;
  while (text && (n = fread(text + size, 1, capacity - size - 1, f)) > 0) {
    size += n;
    if (capacity - size < 2) text = realloc(text, capacity *= 2);
  }
  fclose(f);
  if (text) text[size] = '\0';
  return text;
}

/* A .tri line: 9 numbers, then none, 3 or 9 colour values; '#' starts a comment, and a texture
 * section ("uvw" and nine numbers, format version 2) is not used here. Returns the number of
 * values read (0 for a blank line). */
static int parse_line(char* line, double values[18]) {
  char* hash = strchr(line, '#');
  if (hash) *hash = '\0';
  char* texture = strstr(line, "uvw");
  if (texture) *texture = '\0';
  int count = 0;
  for (char* token = strtok(line, " \t\r\n"); token && count < 18; token = strtok(NULL, " \t\r\n"))
    values[count++] = strtod(token, NULL);
  return count;
}

static int check(int status, const char* what) {
  if (status != RASTERSIM_OK) fprintf(stderr, "scoreboard: %s: %s\n", what, rastersim_last_error());
  return status;
}

int main(int argc, char** argv) {
  if (argc != 5) {
    fprintf(stderr, "usage: scoreboard PROFILE.json TRIANGLES.tri FRAGMENTS.csv BUFFERS.txt\n");
    return 2;
  }
  char* profile = read_file(argv[1]);
  if (!profile) {
    fprintf(stderr, "scoreboard: cannot read %s\n", argv[1]);
    return 2;
  }
  rastersim_pipeline* pipeline = NULL;
  if (check(rastersim_create(profile, &pipeline), argv[1])) return 2;
  free(profile);

  FILE* tri = fopen(argv[2], "r");
  FILE* fragments = fopen(argv[3], "w");
  FILE* buffers = fopen(argv[4], "w");
  if (!tri || !fragments || !buffers) {
    fprintf(stderr, "scoreboard: cannot open the files\n");
    return 2;
  }
  fprintf(fragments, "tri,x,y,z,pass,r,g,b,cycle\n");
  char line[4096];
  int line_number = 0;
  while (fgets(line, sizeof line, tri)) {
    ++line_number;
    double v[18];
    const int count = parse_line(line, v);
    if (count == 0) continue;
    if (count != 9 && count != 12 && count != 18) {
      fprintf(stderr, "scoreboard: %s:%d: %d values, expected 9, 12 or 18\n", argv[2], line_number, count);
      return 2;
    }
    rastersim_screen_vertex vertices[3];
    for (int k = 0; k < 3; ++k) {
      const double* colour = count == 9 ? NULL : count == 12 ? v + 9 : v + 9 + 3 * k;
      vertices[k].x = v[3 * k];
      vertices[k].y = v[3 * k + 1];
      vertices[k].z = v[3 * k + 2];
      vertices[k].r = colour ? (uint8_t)colour[0] : 255;
      vertices[k].g = colour ? (uint8_t)colour[1] : 255;
      vertices[k].b = colour ? (uint8_t)colour[2] : 255;
    }
    int64_t index = 0;
    if (check(rastersim_submit_screen(pipeline, vertices, &index), argv[2])) return 2;

    /* What a scoreboard compares per triangle: the cycle record, the setup record, the fragments. */
    rastersim_triangle_record record;
    check(rastersim_read_triangle(pipeline, index, &record), "triangle record");
    printf("triangle %lld: status %d, setup %lld..%lld, walker %lld..%lld, %lld fragments\n", (long long)index,
           record.status, (long long)record.setup_accept, (long long)record.setup_done,
           (long long)record.walker_load, (long long)record.walker_end, (long long)record.fragments);
    if (record.status == RASTERSIM_DRAWN) {
      rastersim_setup_record setup;
      check(rastersim_read_setup(pipeline, index, &setup), "setup record");
      printf("  box (%d, %d)..(%d, %d), edge 0 start %lld, depth start %lld\n", setup.x0, setup.y0, setup.x1,
             setup.y1, (long long)setup.edge_start[0], (long long)setup.depth_start);
    }
    for (int64_t k = 0; k < record.fragments; ++k) {
      rastersim_fragment f;
      check(rastersim_read_fragment(pipeline, index, k, &f), "fragment");
      fprintf(fragments, "%lld,%d,%d,%u,%d,%d,%d,%d,%lld\n", (long long)f.triangle, f.x, f.y, f.z, f.pass, f.r, f.g,
              f.b, (long long)f.cycle);
    }
  }
  int64_t cycles = 0;
  check(rastersim_frame_cycles(pipeline, &cycles), "cycles");
  printf("cycles %lld\n", (long long)cycles);

  /* The final buffers, one line per pixel in row-major order: depth and colour (0xRRGGBB). */
  int32_t width = 0, height = 0;
  rastersim_width(pipeline, &width);
  rastersim_height(pipeline, &height);
  for (int32_t y = 0; y < height; ++y)
    for (int32_t x = 0; x < width; ++x) {
      uint32_t depth = 0, rgb = 0;
      check(rastersim_read_depth(pipeline, x, y, &depth), "depth");
      check(rastersim_read_color(pipeline, x, y, &rgb), "colour");
      fprintf(buffers, "%u %06x\n", depth, rgb);
    }
  fclose(tri);
  fclose(fragments);
  fclose(buffers);
  rastersim_destroy(pipeline);
  return 0;
}
