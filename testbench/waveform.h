// Waveform files of the RTL backend: an FST written by Verilator, converted to VCD on request, and a
// GTKWave save file that opens it with the units' ports grouped (docs/debugging.md).
#pragma once

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace rastersim::rtl {

// Opens Verilator's FST writer `trace` on `path`; a file that cannot be made is an error here, not
// an empty waveform found later.
template <class Trace>
void open_waveform(Trace& trace, const std::string& path) {
  errno = 0;
  trace.open(path.c_str());
  if (!trace.isOpen())
    throw std::runtime_error("cannot write the waveform " + path + (errno ? " (" + std::string(std::strerror(errno)) + ")" : ""));
}

// The GTKWave save file of the waveform at `wave_path`: its whole name with .gtkw appended
// (w.fst.gtkw, w.vcd.gtkw), so that an FST and a VCD named alike each keep their own.
inline std::string gtkwave_save_path(const std::string& wave_path) { return wave_path + ".gtkw"; }

// Rewrites the FST at `fst_path` as a VCD at `vcd_path` (the same signals and times).
void fst_to_vcd(const std::string& fst_path, const std::string& vcd_path);

// What a GTKWave save file shows when it opens, in FST times: the view from `start` to `end`
// (end < 0: GTKWave's own zoom), the primary marker (-1: none) and named markers A, B, ... in order
// (names without spaces, e.g. "mismatch", "window_start").
struct WaveView {
  int64_t start = 0, end = -1;
  int64_t primary_marker = -1;
  std::vector<std::pair<std::string, int64_t>> markers;
};

// A GTKWave save file for the FST at `fst_path` (read for its signal names), naming `dumpfile` as
// the file to open: a group "frame" (clock, reset, the command handshake, the debug monitor's frame
// cycle and triangle indices) and a group per unit of the pipeline with its ports.
void write_gtkwave_save(const std::string& fst_path, const std::string& dumpfile, const std::string& save_path,
                        const WaveView& view);

// A GTKWave save file for the FST of a design behind the verification interface (cosim --dut),
// naming `dumpfile` as the file to open: the top module's ports in one group.
void write_design_gtkwave_save(const std::string& fst_path, const std::string& dumpfile, const std::string& save_path,
                               const WaveView& view);

}  // namespace rastersim::rtl
