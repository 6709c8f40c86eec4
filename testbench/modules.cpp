#include "testbench/modules.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <vector>

namespace fs = std::filesystem;

namespace rastersim::modules {
namespace {

// The sources a module is built from (testbench/ondemand/CMakeLists.txt reads them from there): an
// installed rastersim's copy, PREFIX/share/rastersim/source beside PREFIX/bin of the running
// program, so that an installed tree stands alone; otherwise the source tree it was built from.
const char* const kSourceFolders[] = {"rtl", "model", "testbench", "cmake"};
const fs::path& source_dir() {
  static const fs::path dir = [] {
    std::error_code error;
    const fs::path program = fs::read_symlink("/proc/self/exe", error);
    if (!error) {
      const fs::path installed = program.parent_path().parent_path() / RASTERSIM_INSTALLED_SOURCE;
      if (fs::is_directory(installed / "testbench" / "ondemand")) return installed;
    }
    return fs::path(RASTERSIM_SOURCE_DIR);
  }();
  return dir;
}

// FNV-1a, 64 bits: a digest for cache keys, not a defence against a malicious cache.
struct Digest {
  uint64_t h = 1469598103934665603ull;
  void add(const void* data, size_t size) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (size_t i = 0; i < size; ++i) h = (h ^ p[i]) * 1099511628211ull;
  }
  void add(const std::string& s) { add(s.data(), s.size() + 1); }  // with the terminator: fields stay apart
  std::string hex() const {
    char out[17];
    std::snprintf(out, sizeof out, "%016llx", static_cast<unsigned long long>(h));
    return out;
  }
};

// The digest of every file of kSourceFolders (paths and contents, in path order).
std::string sources_digest() {
  std::vector<fs::path> files;
  for (const char* folder : kSourceFolders) {
    const fs::path root = source_dir() / folder;
    if (!fs::is_directory(root))
      throw std::runtime_error("cannot build a module: the source folder " + root.string() +
                               " this rastersim was built from is gone (an installed rastersim keeps a copy in "
                               "share/rastersim/source)");
    for (const fs::directory_entry& e : fs::recursive_directory_iterator(root))
      if (e.is_regular_file()) files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  Digest d;
  for (const fs::path& f : files) {
    std::ifstream in(f, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    d.add(fs::relative(f, source_dir()).string());
    d.add(bytes);
  }
  return d.hex();
}

std::string describe(Kind kind, const CoreParameters& parameters) {
  return std::string(kind == Kind::Rtl ? "the verilated RTL" : "the SystemC core") + " with " +
         core_parameters_text(parameters);
}

// Runs argv with stdout and stderr into `log`, passing each output line to `on_line`. Returns the
// exit status (128 + signal when killed).
int run_logged(const std::vector<std::string>& argv, std::ostream& log, const std::function<void(const std::string&)>& on_line) {
  int pipe_fds[2];
  if (pipe(pipe_fds) != 0) throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error(std::string("fork: ") + std::strerror(errno));
  if (pid == 0) {
    dup2(pipe_fds[1], 1);
    dup2(pipe_fds[1], 2);
    close(pipe_fds[0]);
    close(pipe_fds[1]);
    execvp(args[0], args.data());
    std::fprintf(stderr, "cannot run %s: %s\n", args[0], std::strerror(errno));
    _exit(127);
  }
  close(pipe_fds[1]);
  std::string pending;
  char buffer[4096];
  for (;;) {
    const ssize_t n = read(pipe_fds[0], buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    log.write(buffer, n);
    pending.append(buffer, size_t(n));
    for (size_t end; (end = pending.find('\n')) != std::string::npos; pending.erase(0, end + 1))
      on_line(pending.substr(0, end));
  }
  close(pipe_fds[0]);
  log.flush();
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

std::string last_lines(const fs::path& file, size_t count) {
  std::ifstream in(file);
  std::deque<std::string> lines;
  for (std::string line; std::getline(in, line);) {
    lines.push_back(line);
    if (lines.size() > count) lines.pop_front();
  }
  std::string out;
  for (const std::string& l : lines) out += "  " + l + "\n";
  return out;
}

// An exclusive lock on `path` for this object's lifetime (flock: released if the process dies).
class FileLock {
 public:
  FileLock(const fs::path& path, const Progress& progress, const std::string& what) {
    fd_ = open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0) throw std::runtime_error("cannot open " + path.string() + ": " + std::strerror(errno));
    if (flock(fd_, LOCK_EX | LOCK_NB) == 0) return;
    progress("waiting for another rastersim that is building " + what);
    while (flock(fd_, LOCK_EX) != 0)
      if (errno != EINTR) throw std::runtime_error("cannot lock " + path.string() + ": " + std::strerror(errno));
  }
  ~FileLock() { close(fd_); }
  FileLock(const FileLock&) = delete;
  FileLock& operator=(const FileLock&) = delete;

 private:
  int fd_ = -1;
};

}  // namespace

std::string cache_root() {
  if (const char* dir = std::getenv("RASTERSIM_CACHE_DIR"); dir && *dir) return dir;
  if (const char* dir = std::getenv("XDG_CACHE_HOME"); dir && *dir) return (fs::path(dir) / "rastersim").string();
  if (const char* home = std::getenv("HOME"); home && *home) return (fs::path(home) / ".cache" / "rastersim").string();
  throw std::runtime_error("no cache folder for built modules: set RASTERSIM_CACHE_DIR (or HOME)");
}

CoreParameters module_parameters(const Profile& profile) { return core_parameters(profile, CoreBounds::Largest); }

namespace {

// One cache entry: `name` (its key at the end), built from the CMake project `project` with
// `defines` into `library`, unless a finished entry is there; `what` names it in messages and
// `config` in the line that starts the build.
std::string cached_build(const std::string& name, const std::string& what, const std::string& config,
                         const fs::path& project,
                         const std::vector<std::string>& defines, const std::string& library,
                         const Progress& progress) {
  const fs::path modules = fs::path(cache_root()) / "modules";
  const fs::path entry = modules / name;
  if (fs::exists(entry / library)) return (entry / library).string();
  std::error_code ec;
  fs::create_directories(modules, ec);
  if (ec) throw std::runtime_error("cannot create the module cache " + modules.string() + ": " + ec.message());
  FileLock lock(modules / (name + ".lock"), progress, what);
  if (fs::exists(entry / library)) return (entry / library).string();  // built while we waited

  // Only the lock holder builds this entry: a staging folder left by an interrupted build is stale.
  for (const fs::directory_entry& e : fs::directory_iterator(modules))
    if (e.path().filename().string().rfind(name + ".staging-", 0) == 0) fs::remove_all(e.path(), ec);
  const fs::path staging = modules / (name + ".staging-" + std::to_string(getpid()));
  const fs::path build = staging / "build";
  fs::create_directories(build);
  const fs::path log_path = staging / "build.log";
  std::ofstream log(log_path);
  progress(what + " is not built in: verilating it into " + entry.string() + "; later runs load it from there");
  std::string last_percent;
  auto on_line = [&](const std::string& line) {
    // cmake --build's "[ 42%] Building CXX object .../name.cpp.o": one line per step of the percentage.
    if (line.size() > 6 && line[0] == '[' && line[5] == ']' && line.compare(1, 4, last_percent) != 0) {
      last_percent = line.substr(1, 4);
      const size_t slash = line.find_last_of("/ ");
      progress("compiling " + line.substr(0, 6) + " " + line.substr(slash + 1));
    }
  };
  const std::string jobs = std::to_string(std::max(1u, std::thread::hardware_concurrency()));
  std::vector<std::string> configure = {RASTERSIM_CMAKE_COMMAND, "-S", project.string(), "-B", build.string(),
                                        "-DCMAKE_BUILD_TYPE=Release", "-DCMAKE_CXX_COMPILER=" RASTERSIM_MODULE_CXX};
  configure.insert(configure.end(), defines.begin(), defines.end());
  const std::vector<std::vector<std::string>> steps = {configure,
                                                       {RASTERSIM_CMAKE_COMMAND, "--build", build.string(), "-j", jobs}};
  for (const std::vector<std::string>& step : steps) {
    if (&step == &steps.front()) progress("verilating (" + config + ")");
    log << "$";
    for (const std::string& a : step) log << " " << a;
    log << "\n";
    if (run_logged(step, log, on_line) != 0) {
      log.close();
      const fs::path kept = modules / (name + ".failed.log");
      fs::rename(log_path, kept, ec);
      fs::remove_all(staging, ec);
      throw std::runtime_error("building " + what + " failed; its log is " + kept.string() + ", ending:\n" +
                               last_lines(kept, 15));
    }
  }
  log.close();
  fs::rename(build / library, staging / library);
  fs::remove_all(build);
  // One rename publishes the entry whole: a reader sees the library only when it is complete.
  fs::rename(staging, entry, ec);
  if (ec) throw std::runtime_error("cannot publish the module " + entry.string() + ": " + ec.message());
  progress("built " + (entry / library).string());
  return (entry / library).string();
}

}  // namespace

std::string module_library(Kind kind, const Profile& profile, const Progress& progress) {
  const CoreParameters parameters = module_parameters(profile);
  const std::string config = "module:" + core_parameters_text(parameters, ",");
  Digest key;
  key.add(kind == Kind::Rtl ? "rtl" : "systemc");
  key.add(config);
  key.add(RASTERSIM_MODULE_TOOLCHAIN);
  key.add(abi_stamp());
  key.add(sources_digest());
  // The entry's name: the kind, the parameters' values in core_parameters() order, the key.
  std::string name = kind == Kind::Rtl ? "rtl" : "systemc";
  for (const CoreParameter& c : parameters) name += "-" + std::to_string(c.value);
  name += "-" + key.hex();
  return cached_build(name, describe(kind, parameters), config, source_dir() / "testbench/ondemand",
                      {std::string("-DRASTERSIM_MODULE_KIND=") + (kind == Kind::Rtl ? "rtl" : "systemc"),
                       "-DRASTERSIM_MODULE_CONFIG=" + config},
                      kind == Kind::Rtl ? "librastersim_module.so" : "librastersim_systemc.so", progress);
}

std::string dut_library(const DutDesign& design, const Progress& progress) {
  Digest key;
  key.add("dut");
  key.add(design.unit);
  key.add(design.top);
  for (const std::string& p : design.parameters) key.add(p);
  for (const std::string& d : design.include_dirs) key.add(d);
  for (const std::string& f : design.files) {
    key.add(f);
    std::ifstream in(f, std::ios::binary);
    if (!in) throw std::runtime_error("cannot read the design's file " + f);
    key.add(std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>()));
  }
  key.add(RASTERSIM_MODULE_TOOLCHAIN);
  key.add(abi_stamp());
  key.add(sources_digest());
  const auto joined = [](const std::vector<std::string>& items) {
    std::string out;
    for (const std::string& i : items) out += (out.empty() ? "" : ";") + i;
    return out;
  };
  std::string params;
  for (const std::string& p : design.parameters) params += " " + p;
  const std::string unit = design.unit.empty() ? "" : design.unit + "-";
  return cached_build("dut-" + unit + design.top + "-" + key.hex(),
                      (design.unit.empty() ? "the design " : "the " + design.unit + " unit ") + design.top + params,
                      "dut:" + unit + design.top + params, source_dir() / "testbench/dut",
                      {"-DRASTERSIM_DUT_TOP=" + design.top, "-DRASTERSIM_DUT_FILES=" + joined(design.files),
                       "-DRASTERSIM_DUT_INCLUDES=" + joined(design.include_dirs),
                       "-DRASTERSIM_DUT_PARAMETERS=" + joined(design.parameters),
                       "-DRASTERSIM_DUT_UNIT=" + design.unit},
                      "librastersim_dut.so", progress);
}
}  // namespace rastersim::modules
