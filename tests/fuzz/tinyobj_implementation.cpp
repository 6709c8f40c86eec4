// tinyobjloader compiled from Debian's header (the same release as the libtinyobjloader_double the
// product links), so that the fuzzer instruments and sanitizes the OBJ parser itself too.
#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>
