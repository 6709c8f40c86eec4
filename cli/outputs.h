// The outputs of `rastersim render`: images through OpenImageIO, the fragment trace CSV, the stats
// JSON and the human summary. Every regular file is written to a temporary beside its final path
// and renamed into place only when all of them are complete, so a failed run leaves no partial file.
// A symlink is followed (its target is replaced, the link stays); a device, a FIFO, a file with
// other hard links, and `-` (standard output) are written directly, never replaced.
#pragma once

#include <cstdint>
#include <fstream>
#include <ostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "model/pipeline.h"

namespace rastersim {

// The final memories of a frame, from any backend: row-major words, colour 0x00RRGGBB.
struct FrameBuffers {
  int width = 0, height = 0;
  std::vector<uint32_t> depth, color;
};

}  // namespace rastersim

namespace rastersim {

// A path's extension in lower case, with its dot ("" when it has none): what selects a format.
std::string lower_extension(const std::string& path);

class OutputFiles {
 public:
  OutputFiles() = default;
  OutputFiles(const OutputFiles&) = delete;
  OutputFiles& operator=(const OutputFiles&) = delete;
  ~OutputFiles();  // removes every temporary that was not committed

  // An input of this run: no output may resolve to it.
  void protect(const std::string& input_path);
  // Checks that the final path can be written (its folder exists, it is not a folder, no other
  // output names it, it is not an input) and returns the path to write: a temporary, or the target
  // itself when it is written directly. Throws InputError naming the option (`what`, e.g. "-o")
  // and the path. Creates nothing. `seekable`: the writer needs a regular file, so a device or FIFO
  // gets a temporary too, whose bytes are copied into it at commit (never replaced).
  std::string add(const std::string& final_path, const std::string& what, bool seekable = false);
  // Throws InputError when the path resolves to an input of this run: for files a command writes
  // itself (cosim --export's replays).
  void refuse_input(const std::string& final_path, const std::string& what) const;
  // Throws InputError when an input of this run lies inside `folder` (links resolved): for a
  // folder a command replaces as a whole (vectors --out --force).
  void refuse_inputs_inside(const std::string& folder, const std::string& what) const;
  // True when an output is `-`: the human summary then goes to standard error.
  bool writes_stdout() const { return writes_stdout_; }
  // Renames every temporary into place.
  void commit();
  // A scratch file of the run (not an output): removed when the run ends, committed or not, and on
  // a terminating signal. Returns the path.
  std::string add_scratch(const std::string& path);
  // A folder this run created for its outputs (sweep --out): removed, when empty, if the run ends
  // without commit or a terminating signal ends it.
  void remove_uncommitted_folder(const std::string& folder);

 private:
  struct Entry {
    std::string final_path;  // as given
    std::string target;      // where it ends up: the symlink's target, or the path itself
    std::string temp_path;   // what is written: a temporary beside the target, or the target (direct)
    bool direct;
    bool copy = false;  // the temporary is copied into the target (a seekable output's device or FIFO)
  };
  std::vector<Entry> entries_;
  std::vector<std::string> protected_;
  std::vector<std::string> scratch_;
  std::vector<std::string> created_folders_;
  bool committed_ = false;
  bool writes_stdout_ = false;
};

// How an output path is opened: appended to when it is standard output, else truncated.
std::ios::openmode output_mode(const std::string& path);

// Temporaries that a terminating signal (SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGUSR1, SIGALRM, SIGXFSZ,
// ...) removes before the process ends (OutputFiles registers
// its own); install the handlers once, in main.
void remember_temporary(const std::string& path);
void forget_temporary(const std::string& path);
// The same for a hidden folder of files (a vector package being written): the handler removes its
// files and then the folder. Matches vectors::TemporaryFolderHook.
void remember_temporary_folder(const std::string& path, bool exists);
// An empty folder a run created: the handler removes it (rmdir) after the temporaries in it.
void remember_created_folder(const std::string& path, bool exists);
void remove_temporaries_on_signals();

// The RTL waveform options of render and cosim: `--wave FILE` (.fst or .vcd; `--fst` is its
// older name), `--wave-from CYCLE` and `--wave-to CYCLE` (frame cycles, inclusive).
struct WaveOptions {
  std::string path;
  int64_t from = -1, to = -1;  // -1: not given
};
void add_wave_options(CLI::App& command, WaveOptions& options, const std::string& which);

// The waveform and its GTKWave save file (the waveform's whole name with .gtkw appended) as outputs of `outputs`:
// the same checks as every output, written to temporaries and renamed into place with the others.
// `-` is refused (the FST writer seeks), as are another extension and a bad window.
struct WaveFiles {
  std::string wave_temp, save_temp;
  bool vcd = false;
  std::string fst_scratch;  // a VCD is an FST first, written here
};
WaveFiles add_waveform(OutputFiles& outputs, const WaveOptions& options);
// The waveform fields of rtl::RtlOptions from a command's waveform outputs.
template <class RtlOptions>
void set_wave_fields(RtlOptions& options, const WaveFiles& files, const WaveOptions& wave) {
  options.wave_path = files.wave_temp;
  options.wave_vcd = files.vcd;
  options.wave_from = wave.from;
  options.wave_to = wave.to;
  options.gtkwave_save_path = files.save_temp;
  options.wave_name = wave.path;
  options.wave_fst_scratch = files.fst_scratch;
}
// Throws when the simulation left no waveform (a failed write is an error, not silence), or when
// the window starts past the frame's last cycle (`frame_cycles` cycles: 0 .. frame_cycles - 1).
void check_waveform_written(const WaveFiles& files, const WaveOptions& options, int64_t frame_cycles);

// Throws InputError when OpenImageIO has no writer for the path's extension.
void check_image_format(const std::string& path, const std::string& what);

// Colour buffer (0x00RRGGBB words, row 0 at the top) as 8-bit RGB in the format the final path's
// extension names, written to temp_path.
void write_color_image(const std::string& final_path, const std::string& temp_path, const FrameBuffers& buffers);

// Depth buffer as one channel: float32 depth / (2^N - 1) for exr, tif, tiff; otherwise (png,
// ...) uint16 round(depth * 65535 / (2^N - 1)), converted by OpenImageIO where the format needs it.
void write_depth_image(const std::string& final_path, const std::string& temp_path, const FrameBuffers& buffers,
                       int z_bits);
bool depth_image_is_float(const std::string& path);

// The fragment trace: header `tri,x,y,z,pass,r,g,b,cycle`, one row per fragment in emission order.
class FragmentCsvWriter : public FragmentSink {
 public:
  // Writes to `path`; errors name `shown_path`, the output the user asked for.
  FragmentCsvWriter(const std::string& path, const std::string& shown_path);
  ~FragmentCsvWriter() override;
  void on_fragment(const Fragment& fragment) override;
  void close();  // flushes; throws std::runtime_error on a write error (as does a failed flush)
  int64_t rows() const { return rows_; }

 private:
  void flush_buffer();
  std::string shown_path_;
  std::ofstream out_;
  std::string buffer_;
  int64_t rows_ = 0;
};

// The stats object of `--stats`: the FrameStats counters, per-unit busy/stall and the profile.
nlohmann::ordered_json stats_to_json(const FrameStats& stats, const Profile& profile);

// Writes text to `path`; throws std::runtime_error naming `shown_path` on failure.
void write_text_file(const std::string& path, const std::string& shown_path, const std::string& text);

// The short human summary printed after every render.
void print_summary(std::ostream& out, const FrameStats& stats);

}  // namespace rastersim
