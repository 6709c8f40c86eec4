#include "sweep_command.h"

#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <fstream>
#include <iostream>
#include <map>
#include <mutex>
#include <set>
#include <sstream>
#include <utility>

#include "backend.h"
#include "frontend/scene.h"
#include "hw_cost.h"
#include "inputs.h"
#include "model/input_error.h"
#include "outputs.h"
#include "parallel.h"

#ifndef RASTERSIM_SOURCE_DIR
#define RASTERSIM_SOURCE_DIR "."
#endif

namespace rastersim {
namespace {

namespace fs = std::filesystem;

const std::vector<std::string>& camera_keys() {
  static const std::vector<std::string> keys = {"near", "far", "fov"};
  return keys;
}

bool is_camera_key(const std::string& key) {
  return std::find(camera_keys().begin(), camera_keys().end(), key) != camera_keys().end();
}

bool parse_number(const std::string& text, double& value) {
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  return !text.empty() && end == text.c_str() + text.size() && std::isfinite(value);
}

// The figures of one sweep point.
struct Point {
  std::vector<std::string> values;  // one per axis
  FrameStats stats;
  double max_depth_error = 0;
  int64_t wrong_depth_tests = 0;
  HardwareCost cost;
};

// The CSV columns after the swept keys: name, how a point gives it, and when it is written.
enum class Needs { Nothing, HwCost, TextureUnit };  // always; with --hw-cost; when a point has the texture unit
struct Column {
  const char* name;
  double (*value)(const Point&);
  Needs needs;
};

// Which of the optional columns a sweep writes.
struct Written {
  bool hw_cost = false, texture_unit = false;
  bool operator()(const Column& c) const {
    return c.needs == Needs::Nothing || (c.needs == Needs::HwCost && hw_cost) ||
           (c.needs == Needs::TextureUnit && texture_unit);
  }
};

double share(int64_t part, int64_t cycles) { return cycles > 0 ? double(part) / double(cycles) : 0.0; }

const std::vector<Column>& figure_columns() {
  static const std::vector<Column> columns = {
      {"cycles", [](const Point& p) { return double(p.stats.cycles); }, Needs::Nothing},
      {"fragments", [](const Point& p) { return double(p.stats.fragments); }, Needs::Nothing},
      {"fragments_per_clock", [](const Point& p) { return share(p.stats.fragments, p.stats.cycles); }, Needs::Nothing},
      {"setup_share", [](const Point& p) { return share(p.stats.setup.busy, p.stats.cycles); }, Needs::Nothing},
      {"stall_share", [](const Point& p) { return share(p.stats.zbuffer.stall, p.stats.cycles); }, Needs::Nothing},
      {"texture_share", [](const Point& p) { return share(p.stats.texture.busy, p.stats.cycles); }, Needs::TextureUnit},
      {"texture_stall_share", [](const Point& p) { return share(p.stats.texture.stall, p.stats.cycles); },
       Needs::TextureUnit},
      {"depth_fails", [](const Point& p) { return double(p.stats.depth_fail); }, Needs::Nothing},
      {"wrong_depth_tests", [](const Point& p) { return double(p.wrong_depth_tests); }, Needs::Nothing},
      {"max_depth_error", [](const Point& p) { return p.max_depth_error; }, Needs::Nothing},
      {"yosys_cells", [](const Point& p) { return double(p.cost.cells); }, Needs::HwCost},
      {"ice40_luts", [](const Point& p) { return double(p.cost.ice40_luts); }, Needs::HwCost},
      {"ice40_ffs", [](const Point& p) { return double(p.cost.ice40_ffs); }, Needs::HwCost},
      {"memory_bits", [](const Point& p) { return double(p.cost.memory_bits); }, Needs::HwCost},
  };
  return columns;
}

std::string format_value(double v) {
  char text[64];
  if (v == std::floor(v) && std::fabs(v) < 1e15)
    std::snprintf(text, sizeof text, "%lld", static_cast<long long>(v));
  else
    std::snprintf(text, sizeof text, "%.6g", v);
  return text;
}

// How curve s is drawn. gnuplot's colours repeat every 8 linetypes, so each further 8 curves take
// another filled point shape (circle, square, triangles, diamond, pentagon), then dashes as well.
std::string curve_style(size_t s) {
  static const int shapes[] = {7, 5, 9, 11, 13, 15};
  const size_t group = s / 8, n_shapes = sizeof shapes / sizeof shapes[0];
  std::string style = "pointtype " + std::to_string(shapes[group % n_shapes]);
  if (group >= n_shapes) style += " dashtype " + std::to_string(2 + (group / n_shapes - 1) % 4);
  return style;
}

std::string plot_file(const Column& c) { return std::string(c.name) + ".png"; }
constexpr const char* kCostPlot = "cycles_vs_ice40_luts.png";

// Inside gnuplot's single quotes a quote is written twice.
std::string gnuplot_quoted(const std::string& text) {
  std::string out;
  for (char c : text) out += c == '\'' ? std::string("''") : std::string(1, c);
  return out;
}

// A word for sh: single-quoted, a quote as '\''.
std::string sh_quoted(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// A PNG that gnuplot finished: it ends with the IEND chunk (a full disk left truncated plots and a
// zero exit status).
bool png_is_complete(const std::string& path) {
  static const unsigned char iend[12] = {0, 0, 0, 0, 'I', 'E', 'N', 'D', 0xAE, 0x42, 0x60, 0x82};
  std::ifstream in(path, std::ios::binary);
  if (!in.seekg(-12, std::ios::end)) return false;
  unsigned char tail[12];
  return bool(in.read(reinterpret_cast<char*>(tail), 12)) && std::equal(tail, tail + 12, iend);
}

// The gnuplot script: one PNG per figure, the first axis along x, one line per combination of the
// other axes' values. Data inline (datablocks), so the script alone redraws the plots.
// `output` maps a plot's file name to what `set output` names (the run writes temporaries).
std::string gnuplot_script(const std::vector<SweepAxis>& axes, const std::vector<Point>& points, const Written& written,
                           const std::string& title,
                           const std::function<std::string(const std::string&)>& output = [](const std::string& f) {
                             return f;
                           }) {
  const SweepAxis& x_axis = axes.front();
  std::vector<double> xs;
  bool numeric = true;
  for (const std::string& v : x_axis.values) {
    double d = 0;
    numeric = numeric && parse_number(v, d);
    xs.push_back(d);
  }
  if (!numeric)
    for (size_t i = 0; i < xs.size(); ++i) xs[i] = double(i);
  const auto [lo, hi] = std::minmax_element(xs.begin(), xs.end());
  const bool log_x = numeric && *lo > 0 && *hi / *lo >= 100;

  // Series: the points grouped by their values of the other axes, in sweep order.
  std::vector<std::string> series_names;
  std::map<std::string, std::vector<const Point*>> series;
  for (const Point& p : points) {
    std::string name;
    for (size_t a = 1; a < axes.size(); ++a) name += (a > 1 ? ", " : "") + axes[a].key + "=" + p.values[a];
    if (!series.count(name)) series_names.push_back(name);
    series[name].push_back(&p);
  }
  auto x_of = [&](const Point& p) {
    const auto it = std::find(x_axis.values.begin(), x_axis.values.end(), p.values[0]);
    return xs[size_t(it - x_axis.values.begin())];
  };

  // The key sits at the right in one column: 800 x 500 leaves the plot about 300 px beside entries
  // of up to 34 characters and holds 20 entries; longer or more entries widen or heighten the
  // canvas (about 9 px per character, 18 px per entry) rather than narrow the plot.
  size_t longest_name = 0;
  for (const std::string& name : series_names) longest_name = std::max(longest_name, name.size());
  const size_t width = 800 + 9 * (std::max<size_t>(longest_name, 34) - 34);
  const size_t height = std::max<size_t>(500, 140 + 18 * series_names.size());

  std::ostringstream gp;
  gp << "# Written by rastersim sweep: " << title << "\n";
  gp << "set terminal pngcairo size " << width << "," << height << " font ',11'\nset grid\nset key outside right top\n";
  gp << "set xlabel '" << x_axis.key << "' noenhanced\n";
  // Every figure is a count, share or error >= 0: from a zero baseline a 0.07 % difference looks
  // like one (autoscaling once made it fill the plot).
  gp << "set yrange [0:*]\n";
  if (log_x) gp << "set logscale x\n";
  // A tic at every swept value, labelled as given.
  gp << "set xtics (";
  for (size_t i = 0; i < x_axis.values.size(); ++i) gp << (i ? ", " : "") << "'" << x_axis.values[i] << "' " << format_value(xs[i]);
  gp << ")\n";
  if (!numeric) gp << "set xrange [-0.5:" << double(x_axis.values.size()) - 0.5 << "]\n";
  const std::vector<Column>& columns = figure_columns();
  for (size_t s = 0; s < series_names.size(); ++s) {
    gp << "$series" << s << " << EOD\n";
    for (const Point* p : series[series_names[s]]) {
      gp << format_value(x_of(*p));
      for (const Column& c : columns) gp << " " << (written(c) ? format_value(c.value(*p)) : "0");
      gp << "\n";
    }
    gp << "EOD\n";
  }
  auto plot = [&](const std::string& file, const std::string& ylabel, size_t column, bool x_is_cycles) {
    gp << "set output '" << gnuplot_quoted(output(file)) << "'\nset title '" << title
       << "' noenhanced\nset ylabel '" << ylabel << "' noenhanced\n";
    gp << "plot ";
    for (size_t s = 0; s < series_names.size(); ++s) {
      const std::string name = series_names[s].empty() ? ylabel : series_names[s];
      gp << (s ? ", " : "") << "$series" << s << " using " << (x_is_cycles ? "2" : "1") << ":" << column + 2
         << " with linespoints " << curve_style(s) << " title '" << name << "' noenhanced";
    }
    gp << "\n";
  };
  for (size_t c = 0; c < columns.size(); ++c)
    if (written(columns[c])) plot(plot_file(columns[c]), columns[c].name, c, false);
  if (written.hw_cost) {  // cycles against area: one point per sweep point
    gp << "unset logscale x\nunset xtics\nset xtics\nset xrange [*:*]\nset xlabel 'cycles'\n";
    const size_t luts = size_t(std::find_if(columns.begin(), columns.end(), [](const Column& c) {
                                 return std::string(c.name) == "ice40_luts";
                               }) - columns.begin());
    plot(kCostPlot, "ice40_luts", luts, true);
  }
  return gp.str();
}

}  // namespace

SweepAxis parse_sweep_axis(const std::string& text) {
  const size_t eq = text.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError("--vary '" + text + "': expected KEY=V1,V2,... (a profile key, or near, far, fov)");
  SweepAxis axis;
  axis.key = text.substr(0, eq);
  const std::vector<std::string>& keys = profile_keys();
  if (std::find(keys.begin(), keys.end(), axis.key) == keys.end() && !is_camera_key(axis.key)) {
    std::string known;
    for (const std::string& k : keys) known += " " + k;
    throw InputError("--vary '" + text + "': unknown key '" + axis.key + "' (profile keys:" + known +
                     "; camera keys: near far fov)");
  }
  std::istringstream values(text.substr(eq + 1));
  for (std::string v; std::getline(values, v, ',');) {
    if (v.empty()) throw InputError("--vary '" + text + "': an empty value");
    if (std::find(axis.values.begin(), axis.values.end(), v) != axis.values.end())
      throw InputError("--vary '" + text + "': value '" + v + "' given twice");
    axis.values.push_back(v);
  }
  if (axis.values.empty()) throw InputError("--vary '" + text + "': no values");
  return axis;
}

namespace {

// Edge-function weights w[k] of the centre of pixel (x, y) (vertex k's weight is w[k] / sum),
// exact integers: coordinates doubled so that the centre (i + 1/2) 2^S is an integer for every S.
void integer_weights(const SnappedTriangle& t, int subpixel_bits, int x, int y, __int128 w[3]) {
  const __int128 px = (2 * __int128(x) + 1) << subpixel_bits, py = (2 * __int128(y) + 1) << subpixel_bits;
  __int128 vx[3], vy[3];
  for (int k = 0; k < 3; ++k) vx[k] = 2 * __int128(t.v[k].x), vy[k] = 2 * __int128(t.v[k].y);
  auto edge = [&](int a, int b) { return (vx[b] - vx[a]) * (py - vy[a]) - (vy[b] - vy[a]) * (px - vx[a]); };
  w[0] = edge(1, 2), w[1] = edge(2, 0), w[2] = edge(0, 1);
}

}  // namespace

double depth_error_lsb(const SnappedTriangle& t, int subpixel_bits, int x, int y, uint32_t z) {
  __int128 w[3];
  integer_weights(t, subpixel_bits, x, y, w);
  const __int128 area = w[0] + w[1] + w[2];
  const __int128 num = w[0] * t.v[0].z + w[1] * t.v[1].z + w[2] * t.v[2].z;
  __int128 diff = __int128(z) * area - num;
  if (diff < 0) diff = -diff;
  return double(static_cast<long double>(diff) / static_cast<long double>(area < 0 ? -area : area));
}

void pixel_weights(const SnappedTriangle& t, int subpixel_bits, int x, int y, long double weight[3]) {
  __int128 w[3];
  integer_weights(t, subpixel_bits, x, y, w);
  const long double area = static_cast<long double>(w[0] + w[1] + w[2]);
  for (int k = 0; k < 3; ++k) weight[k] = static_cast<long double>(w[k]) / area;
}

// A depth word as a fraction of the plane's range: its value (the smallest plane output with that
// word) over 2^Np - 1; the all-ones word is 1.
long double depth_word_fraction(const Profile& p, uint32_t word) {
  if (word == p.depth_max()) return 1;
  return static_cast<long double>(DepthWord(p).decode(word)) / static_cast<long double>((uint64_t(1) << p.depth_plane_bits()) - 1);
}

DepthErrorMeter::DepthErrorMeter(const std::vector<ScreenTriangle>& screen, const std::vector<SnappedTriangle>& snapped,
                                 const Profile& profile, int threads, size_t chunk)
    : screen_(screen), snapped_(snapped), profile_(profile),
      ideal_depth_(size_t(profile.width) * profile.height, depth_word_fraction(profile, profile.depth_clear_value())),
      word_(profile), meter_threads_(threads > 1 ? size_t(threads - 1) : 0), chunk_(std::max<size_t>(1, chunk)),
      filling_(meter_threads_), metering_(meter_threads_), figures_(std::max<size_t>(1, meter_threads_)),
      failures_(meter_threads_) {}

DepthErrorMeter::~DepthErrorMeter() {
  for (std::thread& t : running_) t.join();
}

void DepthErrorMeter::on_fragment(const Fragment& f) {
  const Kept kept{f.tri, f.x, f.y, f.z, f.pass};
  if (meter_threads_ == 0) return meter(kept, figures_[0]);
  filling_[size_t(f.y / kMeterBandRows) % meter_threads_].push_back(kept);
  if (++kept_count_ == chunk_) hand_over();
}

void DepthErrorMeter::hand_over() {
  join();
  std::swap(filling_, metering_);
  kept_count_ = 0;
  for (size_t k = 0; k < meter_threads_; ++k)
    running_.emplace_back([this, k] {
      try {
        for (const Kept& f : metering_[k]) meter(f, figures_[k]);
      } catch (...) {
        failures_[k] = std::current_exception();
      }
      metering_[k].clear();
    });
}

void DepthErrorMeter::join() {
  for (std::thread& t : running_) t.join();
  running_.clear();
  for (std::exception_ptr& failure : failures_)
    if (failure) std::rethrow_exception(std::exchange(failure, nullptr));
}

void DepthErrorMeter::finish() {
  if (kept_count_ > 0) hand_over();
  join();
}

void DepthErrorMeter::check_finished() const {
  if (kept_count_ > 0 || !running_.empty()) throw std::logic_error("DepthErrorMeter: finish() before reading the figures");
}

double DepthErrorMeter::max_depth_error() const {
  check_finished();
  double max = 0;
  for (const Figures& f : figures_) max = std::max(max, f.max);
  return max;
}

int64_t DepthErrorMeter::wrong_depth_tests() const {
  check_finished();
  int64_t wrong = 0;
  for (const Figures& f : figures_) wrong += f.wrong;
  return wrong;
}

void DepthErrorMeter::meter(const Kept& f, Figures& figures) {
  if (f.tri < 0 || size_t(f.tri) >= snapped_.size()) return;
  const SnappedTriangle& t = snapped_[size_t(f.tri)];
  figures.max = std::max(figures.max, depth_error_lsb(t, profile_.subpixel_bits, f.x, f.y, uint32_t(word_.decode(f.z))));
  long double w[3];
  pixel_weights(t, profile_.subpixel_bits, f.x, f.y, w);
  const ScreenTriangle& s = screen_[size_t(f.tri)];
  const long double z = w[0] * s.v[0].z + w[1] * s.v[1].z + w[2] * s.v[2].z;
  long double& stored = ideal_depth_[size_t(f.y) * size_t(profile_.width) + size_t(f.x)];
  bool pass = false;
  switch (profile_.depth_func) {
    case DepthFunc::Never: pass = false; break;
    case DepthFunc::Less: pass = z < stored; break;
    case DepthFunc::Equal: pass = z == stored; break;
    case DepthFunc::LEqual: pass = z <= stored; break;
    case DepthFunc::Greater: pass = z > stored; break;
    case DepthFunc::NotEqual: pass = z != stored; break;
    case DepthFunc::GEqual: pass = z >= stored; break;
    case DepthFunc::Always: pass = true; break;
  }
  if (pass && profile_.depth_write) stored = z;
  figures.wrong += pass != f.pass;
}

CLI::App* add_sweep_command(CLI::App& app, SweepOptions& o) {
  CLI::App* cmd = app.add_subcommand(
      "sweep", "render one scene at every combination of swept profile (and camera) values: CSV, plots, hardware cost");
  add_scene_options(*cmd, o.scene);
  add_texture_options(*cmd, o.scene);
  cmd->add_option("--vary", o.vary,
                  "KEY=V1,V2,...: a profile key (e.g. traversal=bbox,span, memory_latency=1,2,4, z_bits=16,24) or "
                  "a camera key (near, far, fov); repeat for more axes (every combination is run; the first "
                  "axis is the plots' x axis)")
      ->required()
      ->type_name("KEY=V,...");
  cmd->add_option("--backend", o.backend, "model (default; predicts the RTL's cycles exactly) or systemc")
      ->check(CLI::IsMember({"model", "systemc"}))
      ->type_name("NAME");
  cmd->add_option("--out", o.out_dir, "folder for sweep.csv, sweep.gp and the PNG plots (created)")
      ->required()
      ->type_name("DIR");
  cmd->add_flag("--hw-cost", o.hw_cost,
                "synthesize each point's core with yosys (generic cells, iCE40 LUTs and FFs; cached per profile)");
  cmd->add_option("--hw-cost-cache", o.hw_cost_cache, "cache folder of --hw-cost (default ~/.cache/rastersim/hw-cost)")
      ->type_name("DIR");
  cmd->add_option("--rtl-dir", o.rtl_dir, "RTL sources for --hw-cost (default: the source tree's rtl/)")
      ->type_name("DIR");
  cmd->add_flag("!--no-plots", o.plots, "write the CSV and the gnuplot script only");
  cmd->add_option("--jobs", o.jobs, "points rendered in parallel (the results are the same as with 1; default 1)")
      ->type_name("N");
  cmd->add_option("--threads", o.threads,
                  "threads of each point's depth-error meter (the check of every fragment against the exact depth, "
                  "most of a point's time), which splits the rows in bands (the results are the same as with 1; "
                  "default 1; with --jobs J a sweep runs J x N threads)")
      ->type_name("N");
  add_profile_options(*cmd, o.scene.profile);
  return cmd;
}

int run_sweep(const SweepOptions& o) {
  std::vector<SweepAxis> axes;
  std::set<std::string> seen;
  for (const std::string& text : o.vary) {
    axes.push_back(parse_sweep_axis(text));
    if (!seen.insert(axes.back().key).second) throw InputError("--vary: key '" + axes.back().key + "' given twice");
  }
  const Profile base = resolve_profile(o.scene.profile);
  const Backend backend = select_backend(o.backend);
  if (o.jobs < 1 || o.jobs > 256) throw InputError("--jobs " + std::to_string(o.jobs) + " is outside 1..256");
  if (o.threads < 1 || o.threads > 256) throw InputError("--threads " + std::to_string(o.threads) + " is outside 1..256");
  if (o.jobs > 1 && backend == Backend::Systemc)
    throw InputError("--jobs with the SystemC backend: SystemC runs one simulation per process");
  // Every point's profile and camera are checked before anything runs.
  size_t total = 1;
  for (const SweepAxis& a : axes) {
    // Checked before the points are held (4096 x 4096 points once made one 4.4 GB allocation).
    total *= a.values.size();
    if (total > kMaxSweepPoints)
      throw InputError("--vary: the sweep has more than " + std::to_string(kMaxSweepPoints) +
                       " points, the limit (each is a render); sweep fewer values or split the sweep");
  }
  std::vector<Point> points(total);
  std::vector<Profile> profiles(total, base);
  std::vector<RenderOptions> scenes(total, o.scene);
  for (size_t i = 0; i < total; ++i) {
    size_t rest = i;
    points[i].values.resize(axes.size());
    for (size_t a = axes.size(); a-- > 0;) {  // the last axis varies fastest
      const std::string& v = axes[a].values[rest % axes[a].values.size()];
      rest /= axes[a].values.size();
      points[i].values[a] = v;
      if (is_camera_key(axes[a].key)) {
        double d = 0;
        if (!parse_number(v, d)) throw InputError("--vary " + axes[a].key + ": '" + v + "' is not a number");
        (axes[a].key == "near" ? scenes[i].near : axes[a].key == "far" ? scenes[i].far : scenes[i].fov) = {d};
      } else {
        const std::string error = set_profile_key(profiles[i], axes[a].key, v);
        if (!error.empty()) throw InputError("--vary " + axes[a].key + ": " + error);
      }
    }
    const std::vector<std::string> errors = validate(profiles[i]);
    if (!errors.empty()) {
      std::string where;
      for (size_t a = 0; a < axes.size(); ++a) where += (a ? " " : "") + axes[a].key + "=" + points[i].values[a];
      throw InputError("sweep point " + where + ": " + errors.front());
    }
    check_backend_profile(backend, profiles[i]);
  }
  Written written;
  written.hw_cost = o.hw_cost;
  for (const Profile& p : profiles) written.texture_unit = written.texture_unit || p.texture_unit;
  const std::string texture_flags = texture_words(o.scene);
  if (!texture_flags.empty() && !written.texture_unit)
    throw InputError("the texture flags (" + texture_flags + ") need the texture_unit at some point of the sweep");
  Profile texture_profile = base;
  texture_profile.texture_unit = written.texture_unit;
  const TextureBinding texture = texture_binding(o.scene, o.scene.input, o.scene.scene, texture_profile);
  if (o.plots && std::system("gnuplot --version > /dev/null 2>&1") != 0)
    throw InputError("gnuplot is not installed (scripts/install-deps.sh installs gnuplot-nox), or use --no-plots");
  // Every output is checked before any point runs: none may be an input (a profile or texture
  // inside --out), and all are written to temporaries and renamed into place together. A folder
  // made here goes again when the run fails or is killed (registered before it exists).
  OutputFiles outputs;
  std::error_code ec;
  if (!fs::exists(o.out_dir, ec)) outputs.remove_uncommitted_folder(o.out_dir);
  fs::create_directories(o.out_dir, ec);
  if (ec || !fs::is_directory(o.out_dir)) throw InputError("--out " + o.out_dir + ": cannot create the folder");
  outputs.protect(o.scene.input);
  for (const std::string& mesh : frontend::scene_mesh_files(o.scene.input)) outputs.protect(mesh);
  outputs.protect(o.scene.profile.profile_file);
  outputs.protect(o.scene.texture);
  const std::string csv_path = (fs::path(o.out_dir) / "sweep.csv").string();
  const std::string gp_path = (fs::path(o.out_dir) / "sweep.gp").string();
  std::map<std::string, std::string> plot_temps;  // file name in --out -> temporary gnuplot writes
  std::string csv_temp, gp_temp;
  csv_temp = outputs.add(csv_path, "--out");
  gp_temp = outputs.add(gp_path, "--out");
  if (o.plots) {
    std::vector<std::string> plots;
    for (const Column& c : figure_columns())
      if (written(c)) plots.push_back(plot_file(c));
    if (written.hw_cost) plots.push_back(kCostPlot);
    for (const std::string& name : plots) plot_temps[name] = outputs.add((fs::path(o.out_dir) / name).string(), "--out");
  }
  const std::string rtl_dir = o.rtl_dir.empty() ? std::string(RASTERSIM_SOURCE_DIR) + "/rtl" : o.rtl_dir;

  // Points in parallel with --jobs; each one's line is printed in point order.
  std::mutex mutex;            // the printing state and --hw-cost (its syntheses run one at a time)
  size_t printed = 0;
  std::vector<bool> done(total, false);
  auto print_ready = [&] {
    for (; printed < total && done[printed]; ++printed) {
      const Point& point = points[printed];
      std::cout << "[" << printed + 1 << "/" << total << "]";
      for (size_t a = 0; a < axes.size(); ++a) std::cout << " " << axes[a].key << "=" << point.values[a];
      std::cout << ": " << point.stats.cycles << " cycles, " << point.stats.depth_fail << " depth fails, "
                << point.wrong_depth_tests << " wrong depth tests, max depth error " << point.max_depth_error;
      if (o.hw_cost)
        std::cout << ", " << point.cost.ice40_luts << " iCE40 LUTs" << (point.cost.from_cache ? " (cached)" : "");
      std::cout << std::endl;
    }
  };
  auto run_point = [&](size_t i) {
    Point& point = points[i];
    const Profile& p = profiles[i];
    const std::vector<ScreenTriangle> screen = load_input(o.scene.input, o.scene.scene, p, camera_options(scenes[i]));
    std::vector<SnappedTriangle> snapped;
    snapped.reserve(screen.size());
    for (const ScreenTriangle& t : screen) snapped.push_back(snap(t, p));
    DepthErrorMeter meter(screen, snapped, p, o.threads);
    BackendOptions backend_options;
    backend_options.texture = texture;
    point.stats = render_triangles(backend, p, snapped, &meter, nullptr, backend_options).stats;
    meter.finish();
    point.max_depth_error = meter.max_depth_error();
    point.wrong_depth_tests = meter.wrong_depth_tests();
    std::lock_guard<std::mutex> lock(mutex);
    if (o.hw_cost) point.cost = hardware_cost(p, rtl_dir, o.hw_cost_cache);
    done[i] = true;
    print_ready();
  };
  parallel_for(o.jobs, total, run_point);

  // The CSV, the plot script and the plots, written to temporaries and renamed together.
  std::ostringstream csv;
  for (const SweepAxis& a : axes) csv << a.key << ",";
  bool first = true;
  for (const Column& c : figure_columns())
    if (written(c)) csv << (first ? "" : ",") << c.name, first = false;
  csv << "\n";
  for (const Point& p : points) {
    for (const std::string& v : p.values) csv << v << ",";
    first = true;
    for (const Column& c : figure_columns())
      if (written(c)) csv << (first ? "" : ",") << format_value(c.value(p)), first = false;
    csv << "\n";
  }
  std::string title = o.scene.input.empty() ? "scene " + (o.scene.scene.empty() ? std::string("default") : o.scene.scene)
                                            : fs::path(o.scene.input).filename().string();
  title += ", " + std::to_string(base.width) + "x" + std::to_string(base.height) + ", " + o.backend;
  write_text_file(csv_temp, csv_path, csv.str());
  write_text_file(gp_temp, gp_path, gnuplot_script(axes, points, written, title));
  if (o.plots) {
    // The same script with the temporaries as outputs, run from a scratch file; gnuplot's notes (a
    // constant figure's "empty y range") go to a log, shown only on failure.
    const std::string run_script = outputs.add_scratch(gp_temp + ".run"), log = outputs.add_scratch(gp_temp + ".log");
    write_text_file(run_script, gp_path,
                    gnuplot_script(axes, points, written, title, [&](const std::string& f) { return plot_temps.at(f); }));
    const int status = std::system(("gnuplot " + sh_quoted(run_script) + " 2> " + sh_quoted(log)).c_str());
    if (status != 0) {
      std::ifstream in(log);
      std::cerr << in.rdbuf();
      throw std::runtime_error("gnuplot failed on " + gp_path);
    }
    for (const auto& [name, temp] : plot_temps)
      if (fs::is_regular_file(temp, ec) && !png_is_complete(temp))  // a FIFO or device is not read back
        throw std::runtime_error((fs::path(o.out_dir) / name).string() + ": write error (gnuplot left an incomplete PNG)");
  }
  outputs.commit();
  std::cout << "wrote " << csv_path << "\nwrote " << gp_path << "\n";
  if (o.plots) std::cout << "plotted " << o.out_dir << "/*.png\n";
  return 0;
}

}  // namespace rastersim
