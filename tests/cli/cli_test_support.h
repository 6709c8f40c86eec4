// Helpers for the CLI tests: a scratch folder per test, running the built binary in it, and
// reading back what it wrote (OpenImageIO images, CSV, JSON).
#pragma once

#include <fcntl.h>
#include <pty.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <OpenImageIO/imageio.h>
#include <nlohmann/json.hpp>

namespace rastersim::cli_test {

namespace fs = std::filesystem;

// <tmp>/rastersim-cli-XXXXXX/ holds the captured stdout/stderr; its work/ subfolder is the
// binary's working folder, so a listing of work/ shows exactly what the binary left behind.
class ScratchDir {
 public:
  ScratchDir() {
    std::string pattern = (fs::temp_directory_path() / "rastersim-cli-XXXXXX").string();
    if (!mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed");
    root_ = pattern;
    fs::create_directory(work());
  }
  ~ScratchDir() {
    std::error_code ec;
    fs::remove_all(root_, ec);
  }
  fs::path root() const { return root_; }
  fs::path work() const { return root_ / "work"; }
  fs::path path(const std::string& name) const { return work() / name; }

  void write(const std::string& name, const std::string& text) const {
    std::ofstream out(path(name), std::ios::binary);
    out << text;
  }
  std::set<std::string> listing() const {
    std::set<std::string> names;
    for (const auto& entry : fs::directory_iterator(work())) names.insert(entry.path().filename().string());
    return names;
  }

 private:
  fs::path root_;
};

inline std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

struct RunResult {
  int exit_code = -1;  // -1 when the process did not exit normally (a crash)
  std::string out, err;
};

// Runs the rastersim binary with `args` in dir.work(), stdin from /dev/null. A non-zero
// max_file_bytes limits the size of every file it writes (RLIMIT_FSIZE, with SIGXFSZ ignored so
// that a write past it fails with EFBIG as on a full disk).
inline RunResult run_rastersim(const ScratchDir& dir, const std::vector<std::string>& args,
                               rlim_t max_file_bytes = 0) {
  const std::string out_path = (dir.root() / "stdout.txt").string();
  const std::string err_path = (dir.root() / "stderr.txt").string();
  std::vector<char*> argv;
  std::string exe = RASTERSIM_EXE;
  argv.push_back(exe.data());
  std::vector<std::string> copies = args;
  for (std::string& a : copies) argv.push_back(a.data());
  argv.push_back(nullptr);
  const std::string work = dir.work().string();
  const std::string cache = (dir.root() / "cache").string();
  const pid_t pid = fork();
  if (pid == 0) {
    setenv("RASTERSIM_CACHE_DIR", cache.c_str(), 1);  // a module built on demand stays in the scratch folder
    if (chdir(work.c_str()) != 0) _exit(126);
    const int in = open("/dev/null", O_RDONLY);
    const int out = open(out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err = open(err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (in < 0 || out < 0 || err < 0) _exit(126);
    dup2(in, 0);
    dup2(out, 1);
    dup2(err, 2);
    if (max_file_bytes) {
      signal(SIGXFSZ, SIG_IGN);
      const rlimit limit{max_file_bytes, max_file_bytes};
      if (setrlimit(RLIMIT_FSIZE, &limit) != 0) _exit(126);
    }
    execv(argv[0], argv.data());
    _exit(127);
  }
  RunResult result;
  int status = 0;
  if (pid > 0 && waitpid(pid, &status, 0) == pid && WIFEXITED(status)) result.exit_code = WEXITSTATUS(status);
  result.out = read_text(out_path);
  result.err = read_text(err_path);
  return result;
}

// Runs the binary with its stderr on a pseudo-terminal (as in an interactive shell); stdout goes to
// a file. Returns what the terminal showed as `err`.
inline RunResult run_rastersim_with_terminal_stderr(const ScratchDir& dir, const std::vector<std::string>& args) {
  const std::string out_path = (dir.root() / "stdout.txt").string();
  int master = -1, slave = -1;
  if (openpty(&master, &slave, nullptr, nullptr, nullptr) != 0) throw std::runtime_error("openpty failed");
  std::vector<char*> argv;
  std::string exe = RASTERSIM_EXE;
  argv.push_back(exe.data());
  std::vector<std::string> copies = args;
  for (std::string& a : copies) argv.push_back(a.data());
  argv.push_back(nullptr);
  const std::string work = dir.work().string();
  const std::string cache = (dir.root() / "cache").string();
  const pid_t pid = fork();
  if (pid == 0) {
    setenv("RASTERSIM_CACHE_DIR", cache.c_str(), 1);  // a module built on demand stays in the scratch folder
    close(master);
    setenv("RASTERSIM_PROGRESS_DELAY_MS", "0", 1);  // show progress however fast this machine renders
    if (chdir(work.c_str()) != 0) _exit(126);
    const int in = open("/dev/null", O_RDONLY);
    const int out = open(out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (in < 0 || out < 0) _exit(126);
    dup2(in, 0);
    dup2(out, 1);
    dup2(slave, 2);
    close(slave);
    execv(argv[0], argv.data());
    _exit(127);
  }
  close(slave);
  RunResult result;
  char buffer[4096];
  for (;;) {  // until the child's end of the terminal closes (EIO)
    const ssize_t n = read(master, buffer, sizeof buffer);
    if (n <= 0) break;
    result.err.append(buffer, size_t(n));
  }
  close(master);
  int status = 0;
  if (pid > 0 && waitpid(pid, &status, 0) == pid && WIFEXITED(status)) result.exit_code = WEXITSTATUS(status);
  result.out = read_text(out_path);
  return result;
}

struct Image {
  int width = 0, height = 0, channels = 0;
  std::string format;  // OpenImageIO's TypeDesc name of the stored pixels, e.g. "uint8", "float"
  std::vector<float> pixels;  // as read, normalized by OpenImageIO for integer formats
  std::vector<uint16_t> pixels16;  // the same, read as uint16
  std::vector<uint8_t> pixels8;    // the same, read as uint8
};

inline Image read_image(const fs::path& path) {
  Image image;
  auto in = OIIO::ImageInput::open(path.string());
  if (!in) throw std::runtime_error("cannot open image " + path.string() + ": " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  image.width = spec.width;
  image.height = spec.height;
  image.channels = spec.nchannels;
  image.format = spec.format.c_str();
  const size_t n = size_t(spec.width) * size_t(spec.height) * size_t(spec.nchannels);
  image.pixels.resize(n);
  image.pixels16.resize(n);
  image.pixels8.resize(n);
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.pixels.data()) ||
      !in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT16, image.pixels16.data()) ||
      !in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT8, image.pixels8.data()))
    throw std::runtime_error("cannot read image " + path.string() + ": " + in->geterror());
  in->close();
  return image;
}

struct CsvRow {
  int64_t tri, x, y, z, pass, r, g, b, cycle;
};

struct Csv {
  std::string header;
  std::vector<CsvRow> rows;
};

inline Csv read_fragments_csv(const fs::path& path) {
  Csv csv;
  std::istringstream in(read_text(path));
  std::getline(in, csv.header);
  std::string line;
  while (std::getline(in, line)) {
    CsvRow row{};
    char sep[8];
    std::istringstream fields(line);
    fields >> row.tri >> sep[0] >> row.x >> sep[1] >> row.y >> sep[2] >> row.z >> sep[3] >> row.pass >> sep[4] >>
        row.r >> sep[5] >> row.g >> sep[6] >> row.b >> sep[7] >> row.cycle;
    if (!fields) throw std::runtime_error("bad CSV row: " + line);
    csv.rows.push_back(row);
  }
  return csv;
}

inline nlohmann::json read_json(const fs::path& path) { return nlohmann::json::parse(read_text(path)); }

}  // namespace rastersim::cli_test
