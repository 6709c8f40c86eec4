#include "testbench/vectors/package.h"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "model/core_parameters.h"
#include "model/input_error.h"
#include "model/widths.h"
#include "testbench/rtl_backend.h"
#include "testbench/setup_record.h"
#include "testbench/vectors/package_text.h"
#include "testbench/vectors/rtl_sources.h"

namespace rastersim::vectors {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

uint32_t crc32(const std::string& bytes) {
  static const std::array<uint32_t, 256> table = [] {
    std::array<uint32_t, 256> t{};
    for (uint32_t n = 0; n < 256; ++n) {
      uint32_t c = n;
      for (int k = 0; k < 8; ++k) c = c & 1 ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      t[n] = c;
    }
    return t;
  }();
  uint32_t c = 0xFFFFFFFFu;
  for (const char ch : bytes) c = table[(c ^ uint8_t(ch)) & 0xFF] ^ (c >> 8);
  return c ^ 0xFFFFFFFFu;
}

std::string generator_name() { return std::string("rastersim ") + RASTERSIM_VERSION; }

std::string Source::arguments() const {
  if (kind == "random") return "--random " + std::to_string(count) + " --seed " + std::to_string(seed);
  if (kind == "suite") return "--suite " + name;
  const std::string camera_words = (camera.empty() ? "" : " " + camera) + (texture.empty() ? "" : " " + texture);
  if (kind == "scene") return "--scene " + name + camera_words;
  return name + camera_words;  // a file
}

namespace {

std::string source_text(const Source& s) {
  if (s.kind == "random")
    return std::to_string(s.count) + " constrained-random triangles (rastersim cosim's generator, seed " +
           std::to_string(s.seed) + ")";
  if (s.kind == "suite") return "the directed suite '" + s.name + "'";
  if (s.kind == "scene") return "the built-in scene '" + s.name + "'";
  return "the input file '" + s.name + "'";
}

std::string hex32(uint32_t v) {
  char text[16];
  std::snprintf(text, sizeof text, "0x%08x", v);
  return text;
}

// The profile as command-line flags, every key, in profile_keys() order.
std::string profile_flags(const Profile& profile) {
  const Json j = Json::parse(profile_to_json(profile));
  std::string out;
  for (const std::string& key : profile_keys()) {
    if (!j.contains(key)) continue;
    std::string flag = key;
    std::replace(flag.begin(), flag.end(), '_', '-');
    const Json& v = j[key];
    out += " --" + flag + " " + (v.is_string() ? v.get<std::string>() : v.dump());
  }
  return out;
}

// JSON with small objects and arrays on one line and long arrays of numbers in rows (a manifest a
// person can read).
std::string json_text(const Json& j, int level = 0) {
  const std::string flat = j.dump();
  if (!j.is_structured() || j.empty() || flat.size() + size_t(2 * level) <= 110) return flat;
  const std::string pad(size_t(2 * level + 2), ' ');
  if (j.is_array() && std::all_of(j.begin(), j.end(), [](const Json& e) { return e.is_number(); })) {
    std::string out = "[\n" + pad, row;
    for (size_t i = 0; i < j.size(); ++i) {
      const std::string item = j[i].dump() + (i + 1 < j.size() ? "," : "");
      if (!row.empty() && row.size() + 1 + item.size() > 100) out += row + "\n" + pad, row.clear();
      row += (row.empty() ? "" : " ") + item;
    }
    return out + row + "\n" + std::string(size_t(2 * level), ' ') + "]";
  }
  std::string out = j.is_object() ? "{\n" : "[\n";
  size_t i = 0;
  for (auto it = j.begin(); it != j.end(); ++it, ++i) {
    out += pad;
    if (j.is_object()) out += Json(it.key()).dump() + ": ";
    out += json_text(it.value(), level + 1);
    out += i + 1 < j.size() ? ",\n" : "\n";
  }
  return out + std::string(size_t(2 * level), ' ') + (j.is_object() ? "}" : "]");
}

// The texture record's register 3 g + c (setup_record.h texture_record_field): "s_start",
// "t_step_x", "left1_q_step", ...
std::string texture_register_name(int g, int c) {
  static const char* const groups[] = {"start", "step_x", "step_y", "start", "step", "start", "step"};
  const std::string channel = std::string(1, "stq"[c]) + "_" + groups[g];
  return g < 3 ? channel : "left" + std::to_string((g - 3) / 2) + "_" + channel;
}
std::string texture_register_meaning(int g, int c) {
  const std::string plane = std::string(c == 0 ? "S" : c == 1 ? "T" : "Q");
  switch (g) {
    case 0: return plane + " at the first candidate";
    case 1: return plane + " per pixel in x";
    case 2: return plane + " per pixel in y";
    default:
      return "left-edge slot " + std::to_string((g - 3) / 2) + ": " + plane +
             (g % 2 ? " at the edge's span start on the first row" : "'s change per row without the DDA carry");
  }
}

}  // namespace

Layouts make_layouts(const Profile& p) {
  const Widths w = derive_widths(p);
  Layouts l;
  for (int k = 0; k < 3; ++k) {
    const std::string v = std::to_string(k);
    l.commands.add("x" + v, w.coord_bits, true, "vertex " + v + " x, subpixels (s.S, S = subpixel_bits)");
    l.commands.add("y" + v, w.coord_bits, true, "vertex " + v + " y, subpixels (s.S)");
  }
  for (int k = 0; k < 3; ++k)
    l.commands.add("z" + std::to_string(k), p.depth_plane_bits(), false,
                   "vertex " + std::to_string(k) + " depth (uNp, Np = the depth plane's bits)");
  for (int k = 0; k < 3; ++k)
    l.commands.add("rgb" + std::to_string(k), 24, false, "vertex " + std::to_string(k) + " colour 0xRRGGBB");
  l.texture_unit = p.texture_unit;
  if (p.texture_unit) {  // cmd_textured and cmd_texture0..2 (S, T, Q of docs/arithmetic.md section 5)
    l.commands.add("textured", 1, false, "1: the triangle is textured (S, T, Q below); 0: they are ignored");
    for (int k = 0; k < 3; ++k) {
      const std::string v = std::to_string(k), P = std::to_string(kTextureFractionBits);
      l.commands.add("s" + v, kTextureVertexBits, true, "vertex " + v + " S = u/w in the triangle's scale, s8." + P);
      l.commands.add("t" + v, kTextureVertexBits, true, "vertex " + v + " T = v/w, s8." + P);
      l.commands.add("q" + v, kTextureVertexBits, false, "vertex " + v + " Q = w_min/w, u1." + P + " (at most 1)");
    }
    l.texture.add("rgb", 24, false, "texel 0xRRGGBB; address row * texture width + column, row 0 at v = 0");
  }

  const char* const none = "; -1 (all ones): none";
  l.triangles.add("status", 3, false, "setup decision: 0 drawn, 1 degenerate, 2 culled, 3 offscreen, 4 no centre");
  l.triangles.add("setup_accept", 32, true, "cycle the setup unit accepted the command");
  l.triangles.add("setup_done", 32, true, "cycle its record became valid (drawn) or its decision cycle (rejected)");
  l.triangles.add("walker_load", 32, true, std::string("cycle the walker took the record") + none);
  l.triangles.add("walker_end", 32, true, std::string("walker's last cycle on the triangle") + none);
  l.triangles.add("fragments", 32, false, "fragments the z-buffer took");
  l.triangles.add("depth_pass", 32, false, "of which passed the depth test");
  l.triangles.add("last_write", 32, true, std::string("cycle of its last depth-test result (write)") + none);

  l.setup.add("tri", 32, false, "triangle index (line of commands.hex)");
  for (const rtl::SetupRecordField& f : rtl::setup_record_fields(w, p.shading == Shading::Gouraud))
    l.setup.add(f.name, f.bits, f.is_signed, f.meaning);
  if (p.texture_unit) {  // the texture record (rec_texture: setup_record.h), register 3 g + c
    l.setup.add("textured", 1, false, "the texture record's flag (0: every texture register is 0)");
    for (int g = 0; g < rtl::kTextureRecordGroups; ++g)
      for (int c = 0; c < 3; ++c)
        l.setup.add(texture_register_name(g, c), w.texture_reg_bits, true,
                    "texture plane register, s9.(P+Ft), wrapped: " + texture_register_meaning(g, c));
  }

  l.fragments.add("tri", 32, false, "triangle index");
  l.fragments.add("cycle", 32, true, "cycle the z-buffer took it (frag_valid and frag_ready)");
  l.fragments.add("x", w.x_bits, false, "pixel column");
  l.fragments.add("y", w.y_bits, false, "pixel row");
  l.fragments.add("z", p.z_bits, false, "depth entering the test (uN)");
  l.fragments.add("rgb", 24, false, "colour 0xRRGGBB");
  l.fragments.add("pass", 1, false, "depth test result, memory_latency cycles after its read (results come in fragment order)");

  l.depth.add("depth", p.z_bits, false, "final depth word (uN); address y * width + x");
  l.color.add("rgb", 24, false, "final colour word 0xRRGGBB; address y * width + x");

  const std::pair<const char*, const char*> frame_fields[] = {
      {"cycles", "1 + the last cycle in which setup, walker or z-buffer was busy"},
      {"triangles", "commands accepted"},
      {"triangles_drawn", "setup decisions: drawn"},
      {"triangles_degenerate", "setup decisions: zero area"},
      {"triangles_culled", "setup decisions: culled"},
      {"triangles_offscreen", "setup decisions: the box's pixel-centre columns or rows all beyond the screen"},
      {"triangles_no_centre", "setup decisions: on the screen, no pixel centre in the box"},
      {"candidates", "cycles with trace_walker_candidate"},
      {"fragments", "depth-test results"},
      {"depth_pass", "results with pass"},
      {"depth_fail", "results without pass"},
      {"setup_busy", "cycles with trace_setup_busy and not trace_setup_stall"},
      {"setup_stall", "cycles with trace_setup_stall"},
      {"walker_busy", "cycles with trace_walker_busy"},
      {"walker_stall", "cycles with trace_walker_frag_valid and not trace_walker_frag_ready (the walker's handshake)"},
      {"zbuffer_busy", "cycles with trace_zbuffer_busy"},
      {"zbuffer_stall", "cycles with trace_zbuffer_stall (hazards, memory back-pressure)"},
      {"texture_busy", "cycles with trace_texture_busy (0 without the texture unit)"},
      {"texture_stall", "cycles with trace_texture_stall: a read waiting for the texture memory"},
  };
  for (const auto& [name, meaning] : frame_fields) l.frame.add(name, 32, false, meaning);
  return l;
}

std::vector<VectorFile> vector_files(const Layouts& l) {
  std::vector<VectorFile> files = {
      {"commands.hex", &l.commands, "input: one triangle command per line, in submission order"},
      {"texture.hex", &l.texture, "input: the texture memory image, loaded through texture_load_* during reset"},
      {"triangles.hex", &l.triangles, "expected: one transaction record per triangle (decision and cycles)"},
      {"setup.hex", &l.setup, "expected: the setup record of every drawn triangle (in setup_done), in order"},
      {"fragments.hex", &l.fragments, "expected: every fragment the z-buffer takes, in order"},
      {"depth.hex", &l.depth, "expected: the final depth memory, one word per pixel"},
      {"color.hex", &l.color, "expected: the final colour memory, one word per pixel"},
      {"frame.hex", &l.frame, "expected: the frame's counters (one line)"},
  };
  if (!l.texture_unit) files.erase(files.begin() + 1);
  return files;
}

namespace {

int64_t cycle_field(int64_t v) {
  if (v >= (int64_t(1) << 31))
    throw InputError("the frame takes more than 2^31 cycles; vector packages hold cycle numbers in 32 bits");
  return v;
}

std::string lines(const WordLayout& layout, const std::vector<std::vector<int64_t>>& words) {
  std::string out;
  out.reserve(words.size() * size_t(layout.digits() + 1));
  for (const std::vector<int64_t>& w : words) out += layout.word(w) + "\n";
  return out;
}

using rtl::rgb_word;

}  // namespace

Package build_package(const Profile& profile, const std::vector<SnappedTriangle>& tris, const Source& source,
                      const PackageOptions& options, const TextureBinding& texture) {
  const std::vector<std::string> problems = validate(profile);
  if (!problems.empty()) throw InputError("invalid profile: " + problems.front());
  if (profile.memory_stall_percent > 0 && !options.external_memory)
    throw InputError("memory_stall_percent " + std::to_string(profile.memory_stall_percent) +
                     ": rastersim_top's on-chip memory has no back-pressure; a package of rastersim_core "
                     "(--top rastersim_core) puts a memory model with the stall pattern on its memory port");
  const rtl::RtlResult model = rtl::run_model(profile, tris, texture);
  const Layouts layouts = make_layouts(profile);
  const Widths widths = derive_widths(profile);
  const std::vector<rtl::SetupRecordField> record_fields =
      rtl::setup_record_fields(widths, profile.shading == Shading::Gouraud);

  std::map<std::string, std::vector<std::vector<int64_t>>> words;  // by file
  for (const SnappedTriangle& t : tris) {
    std::vector<int64_t> w;
    for (const SnappedVertex& v : t.v) w.push_back(v.x), w.push_back(v.y);
    for (const SnappedVertex& v : t.v) w.push_back(v.z);
    for (const SnappedVertex& v : t.v) w.push_back(rgb_word(v.color));
    if (profile.texture_unit) {
      w.push_back(t.textured ? 1 : 0);
      for (const SnappedVertex& v : t.v) w.push_back(v.s), w.push_back(v.t), w.push_back(v.q);
    }
    words["commands.hex"].push_back(w);
  }
  // The texture memory image (no texture bound: the one white texel the model samples then).
  const int log2_texture_width = texture.texture ? texture.texture->log2_width() : 0;
  const int log2_texture_height = texture.texture ? texture.texture->log2_height() : 0;
  if (profile.texture_unit)
    for (int j = 0; j < 1 << log2_texture_height; ++j)
      for (int i = 0; i < 1 << log2_texture_width; ++i)
        words["texture.hex"].push_back({int64_t(texture.texture ? texture.texture->texel(i, j) : 0xFFFFFFu)});
  int64_t drawn = 0;
  for (size_t i = 0; i < model.triangles.size(); ++i) {
    const TriangleRecord& r = model.triangles[i];
    words["triangles.hex"].push_back({int64_t(r.status), cycle_field(r.setup_accept), cycle_field(r.setup_done),
                                      cycle_field(r.walker_load), cycle_field(r.walker_end), r.fragments,
                                      r.depth_pass, cycle_field(r.last_write)});
    if (r.status != SetupStatus::Drawn) continue;
    ++drawn;
    const SetupResult& s = model.setups[i];
    std::vector<int64_t> w = {int64_t(i)};
    for (const rtl::SetupRecordField& f : record_fields) w.push_back(f.get(s));
    if (profile.texture_unit) {
      w.push_back(s.textured ? 1 : 0);
      for (int g = 0; g < rtl::kTextureRecordGroups; ++g)
        for (int c = 0; c < 3; ++c) w.push_back(rtl::texture_record_field(s, g, c));
    }
    words["setup.hex"].push_back(w);
  }
  for (const Fragment& f : model.fragments)
    words["fragments.hex"].push_back({f.tri, cycle_field(f.cycle), f.x, f.y, f.z, rgb_word(f.color), f.pass ? 1 : 0});
  for (size_t a = 0; a < model.depth.size(); ++a)
    words["depth.hex"].push_back({model.depth[a]}), words["color.hex"].push_back({model.color[a]});
  const FrameStats& st = model.stats;
  words["frame.hex"] = {{cycle_field(st.cycles), st.triangles, st.triangles_drawn, st.triangles_degenerate,
                         st.triangles_culled, st.triangles_offscreen, st.triangles_no_centre, st.candidates,
                         st.fragments, st.depth_pass, st.depth_fail, st.setup.busy, st.setup.stall, st.walker.busy,
                         st.walker.stall, st.zbuffer.busy, st.zbuffer.stall, st.texture.busy, st.texture.stall}};

  PackageFacts facts;
  facts.profile = profile;
  facts.widths = widths;
  facts.layouts = layouts;
  facts.triangles = int64_t(tris.size());
  facts.drawn = drawn;
  facts.fragments = int64_t(model.fragments.size());
  facts.cycles = st.cycles;
  facts.words = int64_t(profile.width) * profile.height;
  facts.log2_texture_width = log2_texture_width;
  facts.log2_texture_height = log2_texture_height;
  facts.texture_filter = texture.filter;
  facts.texture_wrap = texture.wrap;
  facts.source_text = source_text(source);
  facts.rtl_included = options.rtl_path.empty();
  facts.rtl_folder = facts.rtl_included ? "rtl" : options.rtl_path;
  facts.testbench_folder = options.testbench_path.empty() ? "." : options.testbench_path;
  facts.external_memory = options.external_memory;
  facts.regenerate_command = "rastersim vectors " + source.arguments() + profile_flags(profile) +
                             (facts.rtl_included ? "" : " --rtl-path " + options.rtl_path) +
                             (options.external_memory ? " --top rastersim_core" : "") +
                             (options.testbench_path.empty() ? "" : " --testbench-path " + options.testbench_path) +
                             " --out DIR";

  Package package;
  package.triangles = facts.triangles;
  package.drawn = drawn;
  package.fragments = facts.fragments;
  package.cycles = st.cycles;
  const std::vector<VectorFile> files = vector_files(layouts);
  package.files.push_back({"README.md", readme_text(facts), false});
  package.files.push_back({kParamsFile, params_text(facts), false});
  package.files.push_back({"run_icarus.sh", icarus_script(facts), true});
  package.files.push_back({"run_verilator.sh", verilator_script(facts), true});
  // The board self-test has no texture memory (a texture unit and its memory do not fit the HX8K).
  const bool selftest = !profile.texture_unit;
  package.files.push_back({"lint_verilator.sh", lint_script(facts, selftest), true});
  if (selftest) {
    package.files.push_back({"run_selftest_icarus.sh", selftest_icarus_script(facts), true});
    package.files.push_back({"build_selftest_hx8k.sh", selftest_hx8k_script(facts), true});
    package.files.push_back({kSelftestCrcFile, selftest_crcs(facts, model.depth, model.color), false});
    package.files.push_back({kSelftestPinFile, selftest_pins(), false});
  }
  for (const EmbeddedFile& f : embedded_package_tools()) {
    const bool testbench = f.name == kTestbenchFile || f.name == kMemoryModelFile || f.name == kSelftestFile ||
                           f.name == kLintWaiverFile;
    if (testbench && !options.testbench_path.empty()) continue;
    if (f.name == kSelftestFile && !selftest) continue;
    package.files.push_back({f.name, std::string(reinterpret_cast<const char*>(f.data), f.size), !testbench});
  }
  for (const VectorFile& f : files) package.files.push_back({f.path, lines(*f.layout, words[f.path]), false});
  if (facts.rtl_included)
    for (const EmbeddedFile& f : embedded_rtl())
      package.files.push_back({std::string("rtl/") + f.name, std::string(reinterpret_cast<const char*>(f.data), f.size), false});

  // The manifest: everything above, described.
  Json m;
  m["format"] = "rastersim-vectors";
  m["format_version"] = kFormatVersion;
  m["generator"] = generator_name();
  m["source"] = Json::object();
  m["source"]["kind"] = source.kind;
  if (source.kind == "random") {
    m["source"]["count"] = source.count;
    m["source"]["seed"] = source.seed;
  } else {
    m["source"]["name"] = source.name;
    if (!source.camera.empty()) m["source"]["camera"] = source.camera;
    if (!source.texture.empty()) m["source"]["texture"] = source.texture;
  }
  m["regenerate"] = facts.regenerate_command;
  m["profile"] = Json::parse(profile_to_json(profile));
  Json wj;
  wj["coord_bits"] = widths.coord_bits;
  wj["x_bits"] = widths.x_bits;
  wj["y_bits"] = widths.y_bits;
  wj["addr_bits"] = widths.addr_bits;
  wj["guard_bits"] = widths.guard_bits;
  wj["edge_bits"] = widths.edge_bits;
  wj["edge_step_x_bits"] = widths.edge_step_x_bits;
  wj["edge_step_y_bits"] = widths.edge_step_y_bits;
  wj["span_rem_bits"] = widths.span_rem_bits;
  wj["z_reg_bits"] = widths.z_reg_bits;
  wj["color_reg_bits"] = widths.color_reg_bits;
  wj["divider_bits"] = widths.divider_bits;
  wj["depth_plane_bits"] = profile.depth_plane_bits();
  const SetupTiming setup = setup_timing(profile);
  wj["setup_drawn_latency"] = setup.drawn_latency;
  wj["setup_rejected_latency"] = setup.rejected_latency;
  m["widths"] = wj;
  Json rtl;
  rtl["top"] = options.external_memory ? "rastersim_core" : "rastersim_top";
  rtl["parameters"] = Json::object();
  for (const CoreParameter& c : core_parameters(profile)) rtl["parameters"][c.name] = c.value;
  rtl["included"] = facts.rtl_included;
  rtl["folder"] = facts.rtl_folder;
  if (facts.rtl_included) {
    rtl["version"] = generator_name() + " rtl/ (the files below, by CRC-32)";
  } else {
    rtl["version"] = "the rastersim repository's rtl/ at the commit that holds this package";
  }
  m["rtl"] = rtl;
  Json file_list = Json::array();
  for (const PackageFile& f : package.files) {
    Json e;
    e["path"] = f.path;
    const auto vf = std::find_if(files.begin(), files.end(), [&](const VectorFile& v) { return v.path == f.path; });
    if (vf != files.end()) {
      e["meaning"] = vf->meaning;
      e["word_bits"] = vf->layout->word_bits();
      e["words"] = std::count(f.content.begin(), f.content.end(), '\n');
    } else if (f.path == "README.md") {
      e["meaning"] = "what the package is, how to run it, every file's bit layout";
    } else if (f.path == kTestbenchFile) {
      e["meaning"] = std::string("self-checking testbench, top module ") + kTestbenchTop + " (the same for every package)";
    } else if (f.path == kSelftestFile) {
      e["meaning"] = "board self-test: the commands from a ROM, the core with its frame memory in block RAM, CRC-32s "
                     "of both memories against selftest.hex, done and pass pins";
    } else if (f.path == kSelftestCrcFile) {
      e["meaning"] = "the board self-test's expected CRC-32s: depth memory, colour memory";
      e["word_bits"] = 32;
      e["words"] = 2;
    } else if (f.path == kSelftestPinFile) {
      e["meaning"] = "pins of the board self-test on the iCE40-HX8K Breakout Board";
    } else if (f.path == "run_selftest_icarus.sh" || f.path == "build_selftest_hx8k.sh") {
      e["meaning"] = f.path == "run_selftest_icarus.sh" ? "simulates the board self-test with Icarus Verilog"
                                                        : "builds the board self-test's iCE40 HX8K bitstream";
    } else if (f.path == kLintWaiverFile) {
      e["meaning"] = "Verilator lint waivers of the testbench, memory model and self-test, each with its reason";
    } else if (f.path == std::string("rtl/") + kLintWaiverFile) {
      e["meaning"] = "Verilator lint waivers of the RTL, each with its reason";
    } else if (f.path == "lint_verilator.sh") {
      e["meaning"] = "lints the testbench and the self-test with Verilator -Wall and the waivers";
    } else if (f.path == kMemoryModelFile) {
      e["meaning"] = "frame memory model with the profile's latency and back-pressure (packages of rastersim_core)";
    } else if (f.path == kParamsFile) {
      e["meaning"] = std::string("the testbench's parameters: profile, widths, vector counts, every field's place");
    } else if (f.path == "run_icarus.sh" || f.path == "run_verilator.sh") {
      e["meaning"] = f.path == "run_icarus.sh" ? "runs the testbench with Icarus Verilog"
                                               : "runs the testbench with verilator --binary";
    } else if (f.path == "check_manifest.py") {
      e["meaning"] = "checks every file's size and CRC-32 against this manifest (the run scripts call it first)";
    } else {
      e["meaning"] = "RTL source of rastersim_top";
    }
    e["bytes"] = f.content.size();
    e["crc32"] = hex32(crc32(f.content));
    if (f.path == kSelftestCrcFile) {
      e["layout"] = Json::array({Json{{"field", "crc32"}, {"bits", 32}, {"signed", false}, {"slot", {31, 0}}}});
    } else if (vf != files.end()) {
      Json fields = Json::array();
      for (const Field& field : vf->layout->fields()) {
        Json fj;
        fj["field"] = field.name;
        fj["bits"] = field.bits;
        fj["signed"] = field.is_signed;
        fj["slot"] = {field.lsb + field.slot_bits - 1, field.lsb};
        fields.push_back(fj);
      }
      e["layout"] = fields;
    }
    file_list.push_back(e);
  }
  m["files"] = file_list;
  Json cycles;
  cycles["total"] = st.cycles;
  cycles["per_triangle_meaning"] =
      "cycles from the triangle's setup_accept to its last event (setup_done, walker_end or last_write), "
      "inclusive; triangles.hex holds every event's cycle";
  Json per = Json::array();
  for (const TriangleRecord& r : model.triangles)
    per.push_back(std::max({r.setup_done, r.walker_end, r.last_write}) - r.setup_accept + 1);
  cycles["per_triangle"] = per;
  m["cycles"] = cycles;
  Json stats;
  stats["triangles"] = st.triangles;
  stats["triangles_drawn"] = st.triangles_drawn;
  stats["fragments"] = st.fragments;
  stats["depth_pass"] = st.depth_pass;
  stats["depth_fail"] = st.depth_fail;
  m["stats"] = stats;
  // The manifest's own CRC-32: of its text with this value written as 0x00000000, so that a changed
  // digit anywhere in it is caught as well (check_manifest.py).
  m["manifest_crc32"] = hex32(0);
  const std::string unsigned_text = json_text(m) + "\n";
  m["manifest_crc32"] = hex32(crc32(unsigned_text));
  package.files.push_back({"manifest.json", json_text(m) + "\n", false});
  return package;
}

namespace {

// A package's manifest and the files it lists, and nothing else: --force replaces only that (a
// user's notes.txt in the folder would go with it).
bool holds_package(const fs::path& dir) {
  std::ifstream in(dir / "manifest.json");
  if (!in) return false;
  const Json j = Json::parse(in, nullptr, false);
  if (j.is_discarded() || !j.is_object() || j.value("format", "") != "rastersim-vectors") return false;
  if (!j.contains("files") || !j["files"].is_array()) return false;
  std::set<std::string> listed = {"manifest.json"};
  for (const Json& f : j["files"])
    if (f.is_object() && f.contains("path") && f["path"].is_string()) listed.insert(f["path"].get<std::string>());
  std::error_code ec;
  for (fs::recursive_directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    if (it->is_directory(ec) && !it->is_symlink(ec)) continue;
    if (!listed.count(it->path().lexically_relative(dir).generic_string())) return false;
  }
  return !ec;
}

fs::path make_temp_dir(const fs::path& parent, const std::string& stem) {
  std::string pattern = (parent / ("." + stem + "-XXXXXX")).string();
  if (!mkdtemp(pattern.data()))
    throw InputError("--out: cannot create a folder in '" + parent.string() + "': " + std::strerror(errno));
  return pattern;
}

fs::path normal_out(const std::string& out_dir) {
  if (out_dir.empty()) throw InputError("--out: no folder given");
  fs::path out = fs::path(out_dir).lexically_normal();
  if (out.filename().empty()) out = out.parent_path();
  return out;
}

fs::path parent_of(const fs::path& out) { return out.parent_path().empty() ? fs::path(".") : out.parent_path(); }

}  // namespace

void check_package_dir(const std::string& out_dir, bool force) {
  const fs::path out = normal_out(out_dir);
  const fs::path parent = parent_of(out);
  std::error_code ec;
  if (!fs::is_directory(parent, ec))
    throw InputError("--out: folder '" + parent.string() + "' does not exist (or is not a folder)");
  if (!fs::exists(out, ec)) return;
  if (!fs::is_directory(out, ec)) throw InputError("--out: '" + out.string() + "' exists and is not a folder");
  if (fs::is_empty(out, ec)) return;
  if (!force) throw InputError("--out: folder '" + out.string() + "' is not empty (--force replaces an existing package)");
  if (!holds_package(out))
    throw InputError("--out: folder '" + out.string() +
                     "' is not empty and holds something other than a rastersim-vectors package (a manifest.json "
                     "and the files it lists); --force replaces only a package");
}

// Holds back the terminating signals (cli/outputs.cpp removes temporaries on each) while alive (or
// until release()): they are delivered when released.
class SignalsHeld {
 public:
  SignalsHeld() {
    sigset_t held;
    sigemptyset(&held);
    for (int s : {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGUSR1, SIGUSR2, SIGALRM, SIGVTALRM, SIGPROF, SIGXCPU, SIGXFSZ})
      sigaddset(&held, s);
    pthread_sigmask(SIG_BLOCK, &held, &previous_);
  }
  ~SignalsHeld() { release(); }
  void release() {
    if (holding_) pthread_sigmask(SIG_SETMASK, &previous_, nullptr);
    holding_ = false;
  }
  SignalsHeld(const SignalsHeld&) = delete;
  SignalsHeld& operator=(const SignalsHeld&) = delete;

 private:
  sigset_t previous_;
  bool holding_ = true;
};

void write_package(const Package& package, const std::string& out_dir, bool force,
                   TemporaryFolderHook temporary_folder) {
  check_package_dir(out_dir, force);
  const fs::path out = normal_out(out_dir);
  const fs::path parent = parent_of(out);
  std::error_code ec;
  const bool exists = fs::exists(out, ec);
  const std::string stem = out.filename().string();
  auto track = [&](const fs::path& path, bool made) {
    if (temporary_folder) temporary_folder(path.string(), made);
  };
  // The folder is made and reported with SIGINT, SIGTERM and SIGHUP held back, and so is its
  // rename into place below: a signal between the two steps would leave it behind.
  SignalsHeld hold;
  const fs::path temp = make_temp_dir(parent, stem + ".tmp");
  track(temp, true);
  hold.release();
  try {
    for (const PackageFile& f : package.files) {
      const fs::path path = temp / f.path;
      fs::create_directories(path.parent_path());
      std::ofstream file(path, std::ios::binary);
      file << f.content;
      file.close();
      if (!file) throw InputError("--out: cannot write '" + (out / f.path).string() + "': " + std::strerror(errno));
      if (f.executable) fs::permissions(path, fs::perms::owner_exec | fs::perms::group_exec | fs::perms::others_exec,
                                        fs::perm_options::add);
    }
    // mkdtemp makes the folder 0700; a package is an ordinary folder.
    fs::permissions(temp, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                              fs::perms::others_read | fs::perms::others_exec);
    SignalsHeld hold_rename;
    track(temp, false);  // from here on it is the package (or gone)
    if (exists && !fs::is_empty(out)) {
      const fs::path old = make_temp_dir(parent, stem + ".old");
      fs::rename(out, old);  // onto the empty folder mkdtemp made
      fs::rename(temp, out);
      fs::remove_all(old);
    } else {
      fs::rename(temp, out);  // replaces an empty folder
    }
  } catch (const fs::filesystem_error& e) {
    fs::remove_all(temp, ec);
    track(temp, false);
    throw InputError("--out: cannot write '" + out.string() + "': " + e.code().message());
  } catch (...) {
    fs::remove_all(temp, ec);
    track(temp, false);
    throw;
  }
}

}  // namespace rastersim::vectors
