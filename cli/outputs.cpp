#include "outputs.h"

#include "testbench/waveform.h"

#include <fcntl.h>
#include <dirent.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <csignal>
#include <cstring>
#include <cstdio>
#include <filesystem>
#include <stdexcept>


#include "model/input_error.h"
#include "plugins.h"

namespace rastersim {
namespace fs = std::filesystem;

namespace {

// Where a symlink chain ends, the last link's target also when it does not exist yet (a dangling
// link: weakly_canonical would stop at the link itself, and the output would replace it). A chain
// longer than the system allows is left to the write, which reports it.
fs::path link_target(fs::path path) {
  std::error_code ec;
  for (int hops = 0; hops < 40 && fs::is_symlink(fs::symlink_status(path, ec)); ++hops) {
    const fs::path next = fs::read_symlink(path, ec);
    if (ec) break;
    path = next.is_absolute() ? next : path.parent_path() / next;
  }
  return fs::weakly_canonical(path, ec);
}

}  // namespace

std::string lower_extension(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

// Standard output (an output named `-`) is appended to: truncating it would empty the file a shell
// redirected it to after what was already written there.
std::ios::openmode output_mode(const std::string& path) {
  return path == "/dev/stdout" ? std::ios::binary | std::ios::app : std::ios::binary | std::ios::trunc;
}

namespace {

// Writes bytes to `path`; errors name `shown_path` (the final path the user asked for).
void write_bytes(const std::string& path, const std::string& shown_path, const char* data, size_t size) {
  std::ofstream out(path, output_mode(path));
  out.write(data, std::streamsize(size));
  out.close();
  if (!out) throw std::runtime_error(shown_path + ": write error (" + std::strerror(errno) + ")");
}

template <typename T>
void write_image(const std::string& final_path, const std::string& temp_path, int width, int height, int channels,
                 PixelType type, const std::vector<T>& pixels) {
  // Encoded in memory by the writer the final path's extension selects, then written with checked writes.
  const std::vector<unsigned char> encoded = encode_image(final_path, width, height, channels, type, pixels.data());
  write_bytes(temp_path, final_path, reinterpret_cast<const char*>(encoded.data()), encoded.size());
}

}  // namespace

OutputFiles::~OutputFiles() {
  for (const std::string& path : scratch_) {
    std::error_code ec;
    fs::remove(path, ec);
    forget_temporary(path);
  }
  if (committed_) return;
  for (const Entry& e : entries_) {
    if (e.direct) continue;  // never remove what the user named
    std::error_code ec;
    fs::remove(e.temp_path, ec);
    forget_temporary(e.temp_path);
  }
  for (const std::string& folder : created_folders_) {
    std::error_code ec;
    if (fs::is_empty(folder, ec)) fs::remove(folder, ec);
    remember_created_folder(folder, false);
  }
}

void OutputFiles::remove_uncommitted_folder(const std::string& folder) {
  created_folders_.push_back(folder);
  remember_created_folder(folder, true);
}

void OutputFiles::protect(const std::string& input_path) {
  if (!input_path.empty()) protected_.push_back(input_path);
}

void add_wave_options(CLI::App& command, WaveOptions& o, const std::string& which) {
  command.add_option("--wave,--fst", o.path, which + "write the RTL waveform: FILE.fst or FILE.vcd, and a GTKWave save file "
                     "with the units' signals grouped beside it, the waveform's name with .gtkw appended "
                     "(FILE.fst.gtkw)")
      ->type_name("FILE");
  command.add_option("--wave-from", o.from, "first frame cycle in the waveform (default: from the start of reset)")
      ->type_name("CYCLE");
  command.add_option("--wave-to", o.to, "last frame cycle in the waveform (default: to the end)")->type_name("CYCLE");
}

WaveFiles add_waveform(OutputFiles& outputs, const WaveOptions& o) {
  if (o.path.empty()) {
    if (o.from >= 0 || o.to >= 0 || o.from < -1 || o.to < -1)
      throw InputError(std::string(o.from != -1 ? "--wave-from" : "--wave-to") + " needs --wave FILE");
    return {};
  }
  if (o.path == "-") throw InputError("--wave needs a file: a waveform cannot go to standard output");
  WaveFiles files;
  // First: a folder or a missing one is named as such. An FST is written by seeking: seekable.
  files.wave_temp = outputs.add(o.path, "--wave", fs::path(o.path).extension() == ".fst");
  const std::string extension = fs::path(o.path).extension().string();
  if (extension != ".fst" && extension != ".vcd")
    throw InputError("--wave " + o.path + ": the name must end in .fst or .vcd (the format)");
  if (o.from < -1 || o.to < -1) throw InputError("--wave-from and --wave-to are frame cycles: 0 or more");
  if (o.from >= 0 && o.to >= 0 && o.from > o.to)
    throw InputError("--wave-from " + std::to_string(o.from) + " is after --wave-to " + std::to_string(o.to));
  files.vcd = extension == ".vcd";
  if (files.vcd) files.fst_scratch = outputs.add_scratch(files.wave_temp + ".fst-part");
  files.save_temp = outputs.add(rtl::gtkwave_save_path(o.path), "--wave's GTKWave save file");
  return files;
}

void check_waveform_written(const WaveFiles& files, const WaveOptions& o, int64_t frame_cycles) {
  if (files.wave_temp.empty()) return;
  if (o.from >= frame_cycles)
    throw InputError("--wave-from " + std::to_string(o.from) + " is past the frame's last cycle " +
                     std::to_string(frame_cycles - 1));
  std::error_code ec;
  const fs::file_status status = fs::status(files.wave_temp, ec);
  if (fs::is_regular_file(status) && fs::file_size(files.wave_temp, ec) == 0)
    throw std::runtime_error("cannot write --wave " + o.path + ": the waveform writer wrote nothing");
  if (!fs::exists(status)) throw std::runtime_error("cannot write --wave " + o.path + ": the waveform writer made no file");
  if (!fs::exists(files.save_temp, ec))
    throw std::runtime_error("cannot write the GTKWave save file beside --wave " + o.path);
}

std::string OutputFiles::add(const std::string& final_path, const std::string& what, bool seekable) {
  if (final_path.empty()) throw InputError(what + " needs a file name");
  std::error_code ec;
  // `-` and a path that is standard output: written as a stream.
  if (final_path == "-") {
    for (const Entry& e : entries_)
      if (e.final_path == "-") throw InputError(final_path, 0, "named by two outputs");
    writes_stdout_ = true;
    entries_.push_back({final_path, "/dev/stdout", "/dev/stdout", true});
    return entries_.back().temp_path;
  }
  // A symlink (or a chain of them) is followed: its target is what gets written, made if missing.
  const fs::path path(final_path);
  const fs::path target = fs::is_symlink(fs::symlink_status(path, ec)) ? link_target(path) : path;
  const fs::path folder = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  if (!fs::is_directory(folder, ec))
    throw InputError(final_path, 0, "cannot write " + what + ": folder '" + folder.string() + "' does not exist");
  const fs::file_status status = fs::status(target, ec);
  if (fs::is_directory(status)) throw InputError(final_path, 0, "cannot write " + what + ": it is a folder");
  if (!target.has_filename()) throw InputError(final_path, 0, "cannot write " + what + ": no file name");
  const bool exists = fs::exists(status);
  if (exists) refuse_input(final_path, what);
  for (const Entry& e : entries_) {
    const bool same = exists && fs::exists(e.target, ec) ? fs::equivalent(e.target, target, ec)
                                                         : fs::weakly_canonical(e.target, ec) == fs::weakly_canonical(target, ec);
    if (same) throw InputError(final_path, 0, "named by two outputs");
  }
  // Devices, FIFOs and sockets are written directly (replacing one by a regular file is the damage
  // this avoids); so is a file with other hard links, which must stay one file.
  const bool direct =
      exists && (!fs::is_regular_file(status) || fs::hard_link_count(target, ec) > 1);
  if (direct && seekable) {
    // A writer that seeks or renames (the FST writer) cannot write a FIFO or device: it writes a
    // temporary in the system's temporary folder, copied into the target at commit.
    const std::string temp = (fs::temp_directory_path(ec) / (".rastersim-" + std::to_string(getpid()) + "-" +
                                                             std::to_string(entries_.size()) + target.extension().string()))
                                 .string();
    entries_.push_back({final_path, target.string(), temp, false, true});
    remember_temporary(temp);
    return temp;
  }
  if (direct) {
    entries_.push_back({final_path, target.string(), target.string(), true});
    return entries_.back().temp_path;
  }
  // The temporary's name stays well inside NAME_MAX (255 bytes) whatever the target's length: a
  // long stem is cut (a writer may choose the format by the extension, which is kept when short).
  std::string stem = target.stem().string();
  std::string extension = target.extension().string();
  if (stem.size() + extension.size() > 160) {
    stem.resize(std::min<size_t>(stem.size(), 100));
    if (extension.size() > 40) extension.clear();
  }
  const std::string temp_name = "." + stem + ".tmp" + std::to_string(getpid()) + "-" +
                                std::to_string(entries_.size()) + extension;
  entries_.push_back({final_path, target.string(), (folder / temp_name).string(), false});
  remember_temporary(entries_.back().temp_path);
  return entries_.back().temp_path;
}

void OutputFiles::refuse_input(const std::string& final_path, const std::string& what) const {
  std::error_code ec;
  for (const std::string& input : protected_) {
    if (fs::equivalent(final_path, input, ec))  // false, with ec set, when either does not exist
      throw InputError(final_path, 0, "cannot write " + what + ": it is an input of this run (" + input + ")");
  }
}

void OutputFiles::refuse_inputs_inside(const std::string& folder, const std::string& what) const {
  std::error_code ec;
  const fs::path inside = fs::weakly_canonical(folder, ec);
  if (ec) return;
  for (const std::string& input : protected_) {
    const fs::path resolved = fs::weakly_canonical(input, ec);
    if (ec) continue;
    // `inside` is a prefix of `resolved`, component by component.
    const auto [end, at] = std::mismatch(inside.begin(), inside.end(), resolved.begin(), resolved.end());
    if (end == inside.end() && resolved != inside)
      throw InputError(folder, 0, "cannot write " + what + " there: it holds an input of this run (" + input + ")");
  }
}

std::string OutputFiles::add_scratch(const std::string& path) {
  remember_temporary(path);
  scratch_.push_back(path);
  return path;
}

void OutputFiles::commit() {
  for (const Entry& e : entries_) {
    if (e.direct) continue;
    std::error_code ec;
    if (e.copy) {
      std::ifstream in(e.temp_path, std::ios::binary);
      std::ofstream out(e.target, output_mode(e.target));
      if (in.peek() != std::ifstream::traits_type::eof()) out << in.rdbuf();
      out.close();
      if (!in || !out) throw std::runtime_error(e.final_path + ": write error (" + std::strerror(errno) + ")");
      fs::remove(e.temp_path, ec);
    } else {
      fs::rename(e.temp_path, e.target, ec);
      if (ec) throw std::runtime_error(e.final_path + ": cannot move the finished file into place: " + ec.message());
    }
    forget_temporary(e.temp_path);
  }
  committed_ = true;
  for (const std::string& folder : created_folders_) remember_created_folder(folder, false);
}

// Temporaries to remove when a signal ends the process: fixed storage, so that the
// handler only reads memory and calls unlink (async-signal-safe).
namespace {
constexpr int kMaxTemporaries = 64;  // a sweep has one per plot
char temporaries[kMaxTemporaries][4096];
volatile sig_atomic_t temporary_used[kMaxTemporaries];

char temporary_folders[kMaxTemporaries][4096];
volatile sig_atomic_t temporary_folder_used[kMaxTemporaries];

char created_folders[kMaxTemporaries][4096];
volatile sig_atomic_t created_folder_used[kMaxTemporaries];

// Removes a folder and what it holds with system calls only (no allocation): files, and folders
// below it up to `depth` levels (a package holds rtl/ and the like, one level).
void remove_folder_at(int parent_fd, const char* folder, int depth) {
  const int fd = openat(parent_fd, folder, O_RDONLY | O_DIRECTORY | O_NOFOLLOW);
  if (fd >= 0) {
    alignas(8) char buffer[4096];
    for (long n; (n = syscall(SYS_getdents64, fd, buffer, sizeof buffer)) > 0;) {
      for (long at = 0; at < n;) {
        struct Entry {
          uint64_t inode;
          int64_t offset;
          unsigned short length;
          unsigned char type;
          char name[1];
        };
        const Entry* e = reinterpret_cast<const Entry*>(buffer + at);
        const bool dot = e->name[0] == '.' && (e->name[1] == '\0' || (e->name[1] == '.' && e->name[2] == '\0'));
        if (!dot) {
          if (e->type == DT_DIR) {
            if (depth > 0) remove_folder_at(fd, e->name, depth - 1);
          } else {
            unlinkat(fd, e->name, 0);
          }
        }
        at += e->length;
      }
    }
    close(fd);
  }
  unlinkat(parent_fd, folder, AT_REMOVEDIR);
}

void remove_temporaries_and_reraise(int signal_number) {
  for (int i = 0; i < kMaxTemporaries; ++i)
    if (temporary_used[i]) unlink(temporaries[i]);
  for (int i = 0; i < kMaxTemporaries; ++i)
    if (temporary_folder_used[i]) remove_folder_at(AT_FDCWD, temporary_folders[i], 3);
  for (int i = 0; i < kMaxTemporaries; ++i)
    if (created_folder_used[i]) rmdir(created_folders[i]);  // only when empty: nothing of anyone else's
  ::signal(signal_number, SIG_DFL);
  ::raise(signal_number);
}
}  // namespace

void remember_temporary(const std::string& path) {
  if (path.size() >= sizeof temporaries[0]) return;
  for (int i = 0; i < kMaxTemporaries; ++i) {
    if (temporary_used[i]) continue;
    std::memcpy(temporaries[i], path.c_str(), path.size() + 1);
    temporary_used[i] = 1;
    return;
  }
}

void forget_temporary(const std::string& path) {
  for (int i = 0; i < kMaxTemporaries; ++i)
    if (temporary_used[i] && path == temporaries[i]) temporary_used[i] = 0;
}

void remember_created_folder(const std::string& path, bool exists) {
  for (int i = 0; i < kMaxTemporaries; ++i) {
    if (exists && !created_folder_used[i] && path.size() < sizeof created_folders[0]) {
      std::memcpy(created_folders[i], path.c_str(), path.size() + 1);
      created_folder_used[i] = 1;
      return;
    }
    if (!exists && created_folder_used[i] && path == created_folders[i]) created_folder_used[i] = 0;
  }
}

void remember_temporary_folder(const std::string& path, bool exists) {
  for (int i = 0; i < kMaxTemporaries; ++i) {
    if (exists && !temporary_folder_used[i] && path.size() < sizeof temporary_folders[0]) {
      std::memcpy(temporary_folders[i], path.c_str(), path.size() + 1);
      temporary_folder_used[i] = 1;
      return;
    }
    if (!exists && temporary_folder_used[i] && path == temporary_folders[i]) temporary_folder_used[i] = 0;
  }
}

void remove_temporaries_on_signals() {
  // Every signal whose default action ends the process (SIGPIPE aside: a closed pipe on standard
  // output is a write error the commands report). A signal the caller ignores stays ignored: with
  // SIGXFSZ ignored a write past RLIMIT_FSIZE fails with EFBIG and is reported, nohup keeps SIGHUP off.
  for (int s : {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGUSR1, SIGUSR2, SIGALRM, SIGVTALRM, SIGPROF, SIGXCPU, SIGXFSZ}) {
    struct sigaction current {};
    if (sigaction(s, nullptr, &current) == 0 && current.sa_handler == SIG_IGN) continue;
    ::signal(s, remove_temporaries_and_reraise);
  }
}

void check_image_format(const std::string& path, const std::string& what) {
  if (!image_format_writable(path)) {
    throw InputError(path, 0, "cannot write " + what + ": no image format for the extension '" +
                                  lower_extension(path) + "' (use png, exr, tif, ...)");
  }
}

void write_color_image(const std::string& final_path, const std::string& temp_path, const FrameBuffers& buffers) {
  const std::vector<uint32_t>& words = buffers.color;
  std::vector<uint8_t> rgb(words.size() * 3);
  for (size_t i = 0; i < words.size(); ++i) {
    rgb[3 * i + 0] = uint8_t(words[i] >> 16);
    rgb[3 * i + 1] = uint8_t(words[i] >> 8);
    rgb[3 * i + 2] = uint8_t(words[i]);
  }
  write_image(final_path, temp_path, buffers.width, buffers.height, 3, PixelType::UInt8, rgb);
}

bool depth_image_is_float(const std::string& path) {
  const std::string ext = lower_extension(path);
  return ext == ".exr" || ext == ".tif" || ext == ".tiff";
}

void write_depth_image(const std::string& final_path, const std::string& temp_path, const FrameBuffers& buffers,
                       int z_bits) {
  const std::vector<uint32_t>& depth = buffers.depth;
  const uint64_t depth_max = (uint64_t(1) << z_bits) - 1;
  if (depth_image_is_float(final_path)) {
    std::vector<float> values(depth.size());
    for (size_t i = 0; i < depth.size(); ++i) values[i] = float(double(depth[i]) / double(depth_max));
    write_image(final_path, temp_path, buffers.width, buffers.height, 1, PixelType::Float, values);
  } else {
    std::vector<uint16_t> values(depth.size());
    for (size_t i = 0; i < depth.size(); ++i) values[i] = uint16_t((depth[i] * uint64_t(65535) + depth_max / 2) / depth_max);
    write_image(final_path, temp_path, buffers.width, buffers.height, 1, PixelType::UInt16, values);
  }
}

FragmentCsvWriter::FragmentCsvWriter(const std::string& path, const std::string& shown_path)
    : shown_path_(shown_path), out_(path, output_mode(path)) {
  if (!out_) throw std::runtime_error(shown_path + ": cannot create the fragment trace (" + std::strerror(errno) + ")");
  buffer_.reserve(1 << 16);
  buffer_ = "tri,x,y,z,pass,r,g,b,cycle\n";
}

FragmentCsvWriter::~FragmentCsvWriter() = default;

void FragmentCsvWriter::on_fragment(const Fragment& f) {
  auto field = [this](int64_t value, char separator) {
    char digits[24];  // any int64 in decimal
    const std::to_chars_result r = std::to_chars(digits, digits + sizeof digits, value);
    buffer_.append(digits, r.ptr);
    buffer_.push_back(separator);
  };
  field(f.tri, ',');
  field(f.x, ',');
  field(f.y, ',');
  field(f.z, ',');
  field(f.pass ? 1 : 0, ',');
  field(f.color.r, ',');
  field(f.color.g, ',');
  field(f.color.b, ',');
  field(f.cycle, '\n');
  ++rows_;
  if (buffer_.size() >= (1 << 16)) flush_buffer();
}

void FragmentCsvWriter::flush_buffer() {
  out_.write(buffer_.data(), std::streamsize(buffer_.size()));
  buffer_.clear();
  // Stop the render at the first failed write rather than after it.
  if (!out_) throw std::runtime_error(shown_path_ + ": write error in the fragment trace (" + std::strerror(errno) + ")");
}

void FragmentCsvWriter::close() {
  flush_buffer();
  out_.close();
  if (!out_) throw std::runtime_error(shown_path_ + ": write error in the fragment trace (" + std::strerror(errno) + ")");
}

nlohmann::ordered_json stats_to_json(const FrameStats& s, const Profile& profile) {
  nlohmann::ordered_json j;
  j["triangles"] = s.triangles;
  j["triangles_culled"] = s.triangles_culled;
  j["triangles_degenerate"] = s.triangles_degenerate;
  j["triangles_offscreen"] = s.triangles_offscreen;
  j["triangles_no_centre"] = s.triangles_no_centre;
  j["triangles_drawn"] = s.triangles_drawn;
  j["candidates"] = s.candidates;
  j["fragments"] = s.fragments;
  j["depth_pass"] = s.depth_pass;
  j["depth_fail"] = s.depth_fail;
  j["cycles"] = s.cycles;
  auto unit = [](const UnitCounters& u) { return nlohmann::ordered_json{{"busy", u.busy}, {"stall", u.stall}}; };
  j["units"] = {{"setup", unit(s.setup)}, {"walker", unit(s.walker)}, {"z_adder", unit(s.z_adder)},
                {"zbuffer", unit(s.zbuffer)}};
  if (profile.texture_unit) j["units"]["texture"] = unit(s.texture);
  j["profile"] = nlohmann::ordered_json::parse(profile_to_json(profile));
  return j;
}

void write_text_file(const std::string& path, const std::string& shown_path, const std::string& text) {
  write_bytes(path, shown_path, text.data(), text.size());
}

void print_summary(std::ostream& out, const FrameStats& s) {
  char line[256];
  std::snprintf(line, sizeof line,
                "triangles  %lld (drawn %lld, culled %lld, degenerate %lld, offscreen %lld, no pixel centre %lld)\n",
                (long long)s.triangles, (long long)s.triangles_drawn, (long long)s.triangles_culled,
                (long long)s.triangles_degenerate, (long long)s.triangles_offscreen, (long long)s.triangles_no_centre);
  out << line;
  std::snprintf(line, sizeof line, "fragments  %lld (depth pass %lld, fail %lld) of %lld candidates\n",
                (long long)s.fragments, (long long)s.depth_pass, (long long)s.depth_fail, (long long)s.candidates);
  out << line;
  std::snprintf(line, sizeof line, "cycles     %lld (%.3f fragments per clock)\n", (long long)s.cycles,
                s.cycles > 0 ? double(s.fragments) / double(s.cycles) : 0.0);
  out << line;
  out << "unit            busy       stall\n";
  const std::pair<const char*, const UnitCounters*> units[] = {
      {"setup", &s.setup}, {"walker", &s.walker}, {"z_adder", &s.z_adder}, {"zbuffer", &s.zbuffer}};
  for (const auto& [name, u] : units) {
    std::snprintf(line, sizeof line, "%-8s %11lld %11lld\n", name, (long long)u->busy, (long long)u->stall);
    out << line;
  }
  if (s.texture.busy > 0) {
    std::snprintf(line, sizeof line, "%-8s %11lld %11lld\n", "texture", (long long)s.texture.busy,
                  (long long)s.texture.stall);
    out << line;
  }
}

}  // namespace rastersim
