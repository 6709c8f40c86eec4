// The frame rendered by several threads with the single-threaded model's every result: the same
// fragments, buffer words, counters, records and cycles (tests/test_threads.cpp).
//
// No cycle depends on a depth test's result or a buffer word, so the frame splits in two:
//  - the timing: the calling thread sets up every triangle and submits it to the pipeline in
//    timing-only mode (Pipeline::set_timing_only): walker, texture unit and z-buffer timing, one
//    serial chain, without stepping the plane registers; it passes each drawn triangle's setup
//    result on to the workers through a ring, in submission order;
//  - the depth tests and writes: threads - 1 worker threads; worker k owns the rows y with
//    (y / kBandRows) % (threads - 1) == k, walks every drawn triangle touching them in submission
//    order, and tests and writes only its own rows' fragments. A pixel's fragments are tested in
//    submission order, as in the single-threaded model; no two threads write the same word.
#pragma once

#include <vector>

// Relative, as in model/: installed, these headers are reached as <rastersim/fast/...>.
#include "../model/pipeline.h"

namespace rastersim {

// Rows per band: whole cache lines of words apart at widths from 16 pixels, and bands small
// enough that a triangle's rows spread over the threads.
constexpr int kBandRows = 8;

// Submits `triangles` to `p` (no fragment sink; its texture, triangle log and buffers as for
// p.submit()) with `threads` threads: afterwards p's stats(), zbuffer() and triangle log are
// those of p.submit() of each triangle. threads <= 1: p.submit() of each, on this thread; else
// this thread and threads - 1 workers.
void render_threaded(Pipeline& p, const std::vector<SnappedTriangle>& triangles, int threads);

// The machine's cores (std::thread::hardware_concurrency, 1 when unknown, at most 256).
int machine_threads();

// The thread count of `rastersim render` and `bench` without --threads: the machine's cores when
// the triangles average at least kThreadedPixels pixels (area, at most the box's on the screen)
// and the frame has at least kThreadedFramePixels, else 1. Passing a triangle between cores costs
// about as much as drawing a hundred pixels, and a smaller frame is done before more threads pay
// for their start (the crossovers measured are in docs/performance.md, "Threads").
constexpr int64_t kThreadedPixels = 128, kThreadedFramePixels = int64_t(1) << 19;
int default_threads(const std::vector<SnappedTriangle>& triangles, const Profile& profile);

}  // namespace rastersim
