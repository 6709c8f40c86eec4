// The C interface of librastersim_images.so (cli/image_plugin.cpp), loaded by cli/plugins.cpp.
#pragma once

#include <cstddef>

extern "C" {
// 1 when OpenImageIO has a writer for the path's extension, else 0.
int rastersim_image_writable(const char* path);
// Encodes width x height x channels pixels of `type` (0 uint8, 1 uint16, 2 float) with the writer
// of the path's extension into a buffer from malloc (*data, *size; the caller frees it with
// rastersim_image_free). 0 on success; otherwise 1 with a message in error[error_size].
int rastersim_image_encode(const char* path, int width, int height, int channels, int type, const void* pixels,
                           unsigned char** data, size_t* size, char* error, size_t error_size);
void rastersim_image_free(unsigned char* data);
// Reads the first subimage of the image file at `path` as 8-bit RGB, top row first, 3 bytes a
// pixel (one channel: grey, repeated; two: grey and alpha; more: the first three; the colour as
// stored, not multiplied by alpha), into a buffer from malloc (*pixels; freed with
// rastersim_image_free). The pixels of an image wider or taller than `max_size` are not read
// (*pixels null, *width and *height set). 0 on success; otherwise 1 with a message in
// error[error_size].
int rastersim_image_decode_rgb8(const char* path, int max_size, int* width, int* height, unsigned char** pixels,
                                char* error, size_t error_size);
}
