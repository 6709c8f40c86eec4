// The test-vector package writer (testbench/vectors/): word layouts, CRC-32, the manifest against
// the files it describes, the --out folder rules, and (with Icarus Verilog) that the generated
// testbench passes the package, fails a package with any single expected word changed, naming
// that word's file, vector index and field, and fails when two commands are swapped.
#include <stdlib.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "model/input_error.h"
#include "testbench/cosim_cases.h"
#include "testbench/vectors/package.h"
#include "testbench/vectors/suites.h"

namespace rastersim::vectors {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

class TempDir {
 public:
  TempDir() {
    std::string pattern = (fs::temp_directory_path() / "rastersim-vectors-XXXXXX").string();
    if (!mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed");
    path_ = pattern;
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

void write_text(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::string join_lines(const std::vector<std::string>& lines) {
  std::string text;
  for (const std::string& line : lines) text += line + "\n";
  return text;
}

// A small package: the depth suite on a 16 x 12 screen, Gouraud (every setup field), latency 3.
Profile small_profile() {
  Profile p;
  p.width = 16;
  p.height = 12;
  p.memory_latency = 3;
  p.depth_func = DepthFunc::LEqual;
  return p;
}

Package small_package(const PackageOptions& options = {}) {
  const Profile p = small_profile();
  return build_package(p, suite_triangles("depth", p), Source{"suite", "depth", 0, 0, "", ""}, options);
}

const PackageFile& file_named(const Package& package, const std::string& path) {
  for (const PackageFile& f : package.files)
    if (f.path == path) return f;
  throw std::runtime_error("no file " + path);
}

TEST(VectorsCrc32, MatchesTheStandardCheckValue) {
  EXPECT_EQ(crc32("123456789"), 0xCBF43926u);  // the CRC-32/ISO-HDLC check value
  EXPECT_EQ(crc32(""), 0u);
}

TEST(VectorsWordLayout, FieldsSitInHexDigitSlotsFromTheTop) {
  WordLayout layout;
  layout.add("a", 5, true, "");
  layout.add("b", 3, false, "");
  layout.add("c", 8, false, "");
  EXPECT_EQ(layout.word_bits(), 20);
  EXPECT_EQ(layout.field("a").lsb, 12);
  EXPECT_EQ(layout.field("a").slot_bits, 8);
  EXPECT_EQ(layout.field("b").lsb, 8);
  EXPECT_EQ(layout.field("c").lsb, 0);
  // -3 sign-extended to 8 bits is 0xfd; 5 zero-extended to 4 bits is 5.
  EXPECT_EQ(layout.word({-3, 5, 0xab}), "fd5ab");
  EXPECT_EQ(layout.parse("fd5ab"), (std::vector<int64_t>{-3, 5, 0xab}));
  EXPECT_EQ(layout.word({15, 7, 0}), "0f700");
  EXPECT_EQ(layout.word({-16, 0, 255}), "f00ff");
  EXPECT_THROW(layout.word({16, 0, 0}), std::logic_error);   // a 5-bit signed field holds -16..15
  EXPECT_THROW(layout.word({-17, 0, 0}), std::logic_error);
  EXPECT_THROW(layout.word({0, 8, 0}), std::logic_error);    // 3 unsigned bits hold 0..7
  EXPECT_THROW(layout.word({0, -1, 0}), std::logic_error);
  EXPECT_THROW(layout.word({0, 0}), std::logic_error);
  EXPECT_THROW(layout.parse("fd5a"), std::invalid_argument);
  EXPECT_THROW(layout.parse("fd5aG"), std::invalid_argument);
}

TEST(VectorsManifest, DescribesEveryFileExactly) {
  const Profile profile = small_profile();
  const Package package = small_package();
  ASSERT_EQ(package.files.back().path, "manifest.json");
  const Json m = Json::parse(package.files.back().content);
  EXPECT_EQ(m["format"], "rastersim-vectors");
  EXPECT_EQ(m["format_version"], kFormatVersion);
  EXPECT_EQ(m["generator"], generator_name());
  EXPECT_EQ(m["profile"], Json::parse(profile_to_json(profile)));
  EXPECT_EQ(m["source"]["kind"], "suite");
  EXPECT_EQ(m["source"]["name"], "depth");

  ASSERT_EQ(m["files"].size(), package.files.size() - 1);  // every file but the manifest itself
  // Its own CRC-32: of its text with the value written as zeros.
  std::string unsigned_text = package.files.back().content;
  const std::string own = "\"manifest_crc32\": \"" + m["manifest_crc32"].get<std::string>() + "\"";
  ASSERT_NE(unsigned_text.find(own), std::string::npos);
  unsigned_text.replace(unsigned_text.find(own), own.size(), "\"manifest_crc32\": \"0x00000000\"");
  char own_crc[16];
  std::snprintf(own_crc, sizeof own_crc, "0x%08x", crc32(unsigned_text));
  EXPECT_EQ(m["manifest_crc32"], own_crc);
  const std::regex hex_word("[0-9a-f]+");
  for (size_t i = 0; i + 1 < package.files.size(); ++i) {
    const PackageFile& f = package.files[i];
    const Json& e = m["files"][i];
    SCOPED_TRACE(f.path);
    EXPECT_EQ(e["path"], f.path);
    EXPECT_FALSE(e["meaning"].get<std::string>().empty());
    EXPECT_EQ(e["bytes"], f.content.size());
    char crc[16];
    std::snprintf(crc, sizeof crc, "0x%08x", crc32(f.content));
    EXPECT_EQ(e["crc32"], crc);
    if (f.path.size() < 4 || f.path.substr(f.path.size() - 4) != ".hex") continue;
    // A $readmemh file: one word per line, word_bits / 4 lowercase hex digits, and a layout whose
    // slots tile the word from word_bits - 1 down to 0.
    const int word_bits = e["word_bits"];
    ASSERT_EQ(word_bits % 4, 0);
    const std::vector<std::string> lines = split_lines(f.content);
    EXPECT_EQ(e["words"], lines.size());
    for (const std::string& line : lines) {
      ASSERT_EQ(int(line.size()), word_bits / 4) << line;
      ASSERT_TRUE(std::regex_match(line, hex_word)) << line;
    }
    int next_msb = word_bits - 1;
    for (const Json& field : e["layout"]) {
      EXPECT_EQ(field["slot"][0], next_msb) << field.dump();
      const int slot_bits = field["slot"][0].get<int>() - field["slot"][1].get<int>() + 1;
      EXPECT_EQ(slot_bits % 4, 0);
      EXPECT_GE(slot_bits, field["bits"].get<int>());
      EXPECT_LT(slot_bits, field["bits"].get<int>() + 4);
      next_msb -= slot_bits;
    }
    EXPECT_EQ(next_msb, -1);
  }

  // Word counts against the frame.
  const Layouts layouts = make_layouts(profile);
  const std::vector<std::string> commands = split_lines(file_named(package, "commands.hex").content);
  const std::vector<std::string> triangles = split_lines(file_named(package, "triangles.hex").content);
  const std::vector<std::string> fragments = split_lines(file_named(package, "fragments.hex").content);
  const std::vector<std::string> setups = split_lines(file_named(package, "setup.hex").content);
  EXPECT_EQ(commands.size(), suite_triangles("depth", profile).size());
  EXPECT_EQ(triangles.size(), commands.size());
  EXPECT_EQ(split_lines(file_named(package, "depth.hex").content).size(), size_t(profile.width * profile.height));
  EXPECT_EQ(split_lines(file_named(package, "color.hex").content).size(), size_t(profile.width * profile.height));
  const std::vector<int64_t> frame = layouts.frame.parse(split_lines(file_named(package, "frame.hex").content).at(0));

  // Per-triangle cycles: from setup_accept to the last of its events, inclusive; all within the
  // frame's total. Per-triangle fragments and passes add up to fragments.hex.
  const auto field_index = [](const WordLayout& l, const std::string& name) {
    const auto& fs = l.fields();
    return size_t(std::find_if(fs.begin(), fs.end(), [&](const Field& f) { return f.name == name; }) - fs.begin());
  };
  const auto tri_field = [&](const std::vector<int64_t>& w, const char* name) {
    return w.at(field_index(layouts.triangles, name));
  };
  const Json& per = m["cycles"]["per_triangle"];
  ASSERT_EQ(per.size(), triangles.size());
  EXPECT_EQ(m["cycles"]["total"], frame.at(field_index(layouts.frame, "cycles")));
  int64_t fragment_sum = 0, pass_sum = 0, drawn = 0;
  for (size_t t = 0; t < triangles.size(); ++t) {
    const std::vector<int64_t> w = layouts.triangles.parse(triangles[t]);
    const int64_t last = std::max({tri_field(w, "setup_done"), tri_field(w, "walker_end"), tri_field(w, "last_write")});
    EXPECT_EQ(per[t], last - tri_field(w, "setup_accept") + 1) << "triangle " << t;
    EXPECT_LT(last, m["cycles"]["total"].get<int64_t>());
    fragment_sum += tri_field(w, "fragments");
    pass_sum += tri_field(w, "depth_pass");
    drawn += tri_field(w, "status") == 0;
  }
  EXPECT_EQ(fragment_sum, int64_t(fragments.size()));
  EXPECT_EQ(drawn, int64_t(setups.size()));
  int64_t passes = 0;
  for (const std::string& line : fragments) passes += layouts.fragments.parse(line).back();  // pass is last
  EXPECT_EQ(pass_sum, passes);
  EXPECT_GT(passes, 0);
  EXPECT_LT(passes, int64_t(fragments.size()));  // lequal over overlaps: some pass, some fail
}

TEST(VectorsPackage, SameInputsGiveTheSameBytes) {
  const Package a = small_package(), b = small_package();
  ASSERT_EQ(a.files.size(), b.files.size());
  for (size_t i = 0; i < a.files.size(); ++i) {
    EXPECT_EQ(a.files[i].path, b.files[i].path);
    EXPECT_TRUE(a.files[i].content == b.files[i].content) << a.files[i].path;
  }
}

TEST(VectorsPackage, RtlIsCopiedUnlessARelativePathIsGiven) {
  const Package copied = small_package();
  EXPECT_NO_THROW(file_named(copied, "rtl/rastersim_top.sv"));
  PackageOptions options;
  options.rtl_path = "../../rtl";
  const Package referring = small_package(options);
  for (const PackageFile& f : referring.files) EXPECT_NE(f.path.rfind("rtl/", 0), 0u) << f.path;
  EXPECT_NE(file_named(referring, "run_icarus.sh").content.find("$here/../../rtl"), std::string::npos);
}

TEST(VectorsOutFolder, RefusesWhatItMustNotOverwrite) {
  TempDir dir;
  const Package package = small_package();
  const fs::path out = dir.path() / "pkg";
  EXPECT_THROW(check_package_dir((dir.path() / "missing" / "pkg").string(), false), InputError);
  write_text(dir.path() / "file", "x");
  EXPECT_THROW(check_package_dir((dir.path() / "file").string(), true), InputError);
  // An empty folder is fine; a folder with something else in it never is.
  fs::create_directory(out);
  EXPECT_NO_THROW(check_package_dir(out.string(), false));
  write_text(out / "notes.txt", "mine");
  EXPECT_THROW(write_package(package, out.string(), false), InputError);
  EXPECT_THROW(write_package(package, out.string(), true), InputError);
  EXPECT_EQ(read_text(out / "notes.txt"), "mine");
  fs::remove(out / "notes.txt");
  // A package is replaced only with force.
  write_package(package, out.string(), false);
  EXPECT_EQ(read_text(out / "manifest.json"), package.files.back().content);
  EXPECT_THROW(write_package(package, out.string(), false), InputError);
  EXPECT_NO_THROW(write_package(package, out.string(), true));
  // Nothing is left beside it (no temporary folders).
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir.path())) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"file", "pkg"}));
}

// docs/vectors.md decodes the first command of vectors/depth-less field by field.
TEST(VectorsDocs, CommandExampleIsWhatThePackageHolds) {
  const std::string doc = read_text(RASTERSIM_SOURCE_DIR "/docs/vectors.md");
  const std::string marker = "\n020 018 ";
  const size_t at = doc.find(marker);
  ASSERT_NE(at, std::string::npos) << "no command example in docs/vectors.md";
  std::string example = doc.substr(at + 1, doc.find('\n', at + 1) - at - 1);
  example.erase(std::remove(example.begin(), example.end(), ' '), example.end());
  const std::string checked_in = read_text(RASTERSIM_SOURCE_DIR "/vectors/depth-less/commands.hex");
  EXPECT_EQ(example, checked_in.substr(0, checked_in.find('\n')));
  const std::string built = file_named(small_package(), "commands.hex").content;  // same screen, same suite
  EXPECT_EQ(example, built.substr(0, built.find('\n')));
}

#if defined(RASTERSIM_IVERILOG) && defined(RASTERSIM_VVP)

struct CommandResult {
  int status = -1;
  std::string output;
};

CommandResult run_command(const std::string& command) {
  CommandResult r;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return r;
  char buffer[4096];
  for (size_t n; (n = fread(buffer, 1, sizeof buffer, pipe)) > 0;) r.output.append(buffer, n);
  const int status = pclose(pipe);
  r.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

std::string last_line(const std::string& text) {
  const std::vector<std::string> lines = split_lines(text);
  return lines.empty() ? "" : lines.back();
}

// The package written to a scratch folder, its testbench compiled once with Icarus; each run
// replays whatever the .hex files hold then.
class IcarusPackage : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = dir_holder_.path() / "pkg";
    write_package(package_, dir_.string(), false);
    const std::string compile = std::string(RASTERSIM_IVERILOG) + " -g2012 -I . -I rtl -s rastersim_vectors_tb -o tb.vvp " +
                                "rastersim_vectors_tb.v rastersim_memory_model.v rtl/*.sv";
    const CommandResult built = run_command("cd '" + dir_.string() + "' && " + compile);
    ASSERT_EQ(built.status, 0) << built.output;
  }
  CommandResult replay(const std::string& plusargs = "", const std::string& vvp = "tb.vvp") const {
    return run_command("cd '" + dir_.string() + "' && " + RASTERSIM_VVP + " -n " + vvp + " " + plusargs);
  }
  // The testbench compiled against a copy of the package's RTL with rastersim_core.sv rewritten by
  // `edit` (a port with another micro-architecture, or a bug); returns the .vvp's name.
  std::string build_variant(const std::string& name, const std::function<std::string(std::string)>& edit) const {
    const fs::path rtl = dir_ / ("rtl_" + name);
    fs::create_directory(rtl);
    for (const fs::directory_entry& e : fs::directory_iterator(dir_ / "rtl")) fs::copy(e.path(), rtl / e.path().filename());
    const std::string core = read_text(rtl / "rastersim_core.sv");
    const std::string edited = edit(core);
    EXPECT_NE(edited, core) << name << ": the edit changed nothing";
    write_text(rtl / "rastersim_core.sv", edited);
    const std::string vvp = name + ".vvp";
    const CommandResult built = run_command("cd '" + dir_.string() + "' && " + RASTERSIM_IVERILOG + " -g2012 -I . -I " +
                                            rtl.filename().string() + " -s rastersim_vectors_tb -o " + vvp +
                                            " rastersim_vectors_tb.v rastersim_memory_model.v " + rtl.filename().string() + "/*.sv");
    EXPECT_EQ(built.status, 0) << built.output;
    return vvp;
  }
  int64_t vector_count() const {
    int64_t n = 0;
    for (const char* file : {"triangles.hex", "setup.hex", "fragments.hex", "depth.hex", "color.hex", "frame.hex"})
      n += int64_t(split_lines(file_named(package_, file).content).size());
    return n;
  }

  TempDir dir_holder_;
  fs::path dir_;
  Package package_ = small_package();
};

TEST_F(IcarusPackage, ChangingAnySingleExpectedWordFailsNamingItsVectorAndField) {
  const CommandResult clean = replay();
  ASSERT_EQ(last_line(clean.output), std::to_string(vector_count()) + " passed, 0 failed") << clean.output;

  // Every field of every expected file, each in a different vector: its lowest bit flipped.
  const Layouts layouts = make_layouts(small_profile());
  struct ExpectedFile {
    std::string path;
    const WordLayout* layout;
  };
  const std::vector<ExpectedFile> files = {
      {"triangles.hex", &layouts.triangles}, {"setup.hex", &layouts.setup}, {"fragments.hex", &layouts.fragments},
      {"depth.hex", &layouts.depth},         {"color.hex", &layouts.color}, {"frame.hex", &layouts.frame}};
  int mutations = 0;
  for (size_t k = 0; k < files.size(); ++k) {
    const std::string original = file_named(package_, files[k].path).content;
    std::vector<std::string> lines = split_lines(original);
    ASSERT_FALSE(lines.empty()) << files[k].path;
    const std::vector<Field>& fields = files[k].layout->fields();
    for (size_t f = 0; f < fields.size(); ++f) {
      const size_t index = (f * 37 + k * 11) % lines.size();
      const std::string word = lines[index];
      const int digit = (files[k].layout->word_bits() - 1 - fields[f].lsb) / 4;  // its lowest digit
      const int value = std::stoi(word.substr(size_t(digit), 1), nullptr, 16) ^ 1;
      lines[index][size_t(digit)] = "0123456789abcdef"[value];
      write_text(dir_ / files[k].path, join_lines(lines));
      lines[index] = word;

      const CommandResult r = replay();
      const std::string expected_first = "first mismatch: " + files[k].path + " vector " + std::to_string(index) +
                                         " field " + fields[f].name + ":";
      EXPECT_NE(r.output.find(expected_first), std::string::npos) << expected_first << "\n" << r.output;
      EXPECT_EQ(last_line(r.output), std::to_string(vector_count() - 1) + " passed, 1 failed") << r.output;
      ++mutations;
    }
    write_text(dir_ / files[k].path, original);
  }
  EXPECT_GT(mutations, 60);
}

// The testbench's plusargs: +max_shown=N prints N mismatches (the rest counted), +dump=FILE a VCD.
TEST_F(IcarusPackage, PlusargsSetTheMismatchesShownAndDumpAWaveform) {
  std::vector<std::string> depth = split_lines(file_named(package_, "depth.hex").content);
  ASSERT_GT(depth.size(), 30u);
  for (const size_t index : {size_t(3), size_t(17), size_t(29)}) {  // the lowest bit of three words
    char& digit = depth[index].back();
    digit = "0123456789abcdef"[std::stoi(std::string(1, digit), nullptr, 16) ^ 1];
  }
  write_text(dir_ / "depth.hex", join_lines(depth));
  auto mismatch_lines = [](const std::string& output) {
    size_t n = 0;
    for (const std::string& line : split_lines(output)) n += line.rfind("first mismatch: ", 0) == 0 || line.rfind("mismatch: ", 0) == 0;
    return n;
  };
  const CommandResult all = run_command("cd '" + dir_.string() + "' && " + RASTERSIM_VVP + " -n tb.vvp");
  EXPECT_EQ(mismatch_lines(all.output), 3u) << all.output;
  const CommandResult one = run_command("cd '" + dir_.string() + "' && " + RASTERSIM_VVP + " -n tb.vvp +max_shown=1");
  EXPECT_EQ(mismatch_lines(one.output), 1u) << one.output;
  EXPECT_NE(one.output.find("(2 more mismatches not shown)"), std::string::npos) << one.output;
  EXPECT_EQ(last_line(one.output), std::to_string(vector_count() - 3) + " passed, 3 failed") << one.output;
  const CommandResult none = run_command("cd '" + dir_.string() + "' && " + RASTERSIM_VVP + " -n tb.vvp +max_shown=0");
  EXPECT_EQ(mismatch_lines(none.output), 0u) << none.output;
  EXPECT_NE(none.output.find("(3 more mismatches not shown)"), std::string::npos) << none.output;
  const CommandResult negative =
      run_command("cd '" + dir_.string() + "' && " + RASTERSIM_VVP + " -n tb.vvp +max_shown=-1");
  EXPECT_NE(negative.output.find("error: +max_shown=-1"), std::string::npos) << negative.output;
  EXPECT_EQ(negative.output.find(" passed, "), std::string::npos) << negative.output;

  const CommandResult dumped =
      run_command("cd '" + dir_.string() + "' && " + RASTERSIM_VVP + " -n tb.vvp +max_shown=0 +dump=run.vcd");
  EXPECT_EQ(last_line(dumped.output), std::to_string(vector_count() - 3) + " passed, 3 failed") << dumped.output;
  std::ifstream vcd(dir_ / "run.vcd");
  const std::string text((std::istreambuf_iterator<char>(vcd)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("$enddefinitions"), std::string::npos);
  EXPECT_NE(text.find("trace_setup_status"), std::string::npos);
  EXPECT_NE(text.find("\n#"), std::string::npos) << "no time step in the VCD";
}

// The time steps of a VCD file (its #N lines).
std::vector<int64_t> vcd_times(const fs::path& path) {
  std::vector<int64_t> times;
  for (const std::string& line : split_lines(read_text(path)))
    if (line.size() > 1 && line[0] == '#') times.push_back(std::stoll(line.substr(1)));
  return times;
}

// +dump_from / +dump_to cut the VCD to a window of frame cycles; a wrong plusarg is exit 2 from the
// run scripts (not 1, which says a vector failed).
TEST_F(IcarusPackage, ADumpWindowHoldsOnlyItsCyclesAndWrongPlusargsExitTwo) {
  const CommandResult whole = replay("+max_shown=0 +dump=whole.vcd");
  ASSERT_EQ(last_line(whole.output), std::to_string(vector_count()) + " passed, 0 failed") << whole.output;
  const CommandResult window = replay("+max_shown=0 +dump=window.vcd +dump_from=20 +dump_to=29");
  ASSERT_EQ(last_line(window.output), std::to_string(vector_count()) + " passed, 0 failed") << window.output;
  const std::vector<int64_t> all = vcd_times(dir_ / "whole.vcd");
  const std::vector<int64_t> cut = vcd_times(dir_ / "window.vcd");
  ASSERT_GT(all.size(), 100u);
  ASSERT_FALSE(cut.empty());
  EXPECT_EQ(all.front(), 0);
  // From the middle of cycle 19 to the middle of cycle 30 (a 10 ns clock, 1 ps steps): 11 cycles.
  EXPECT_GT(cut.front(), 20 * 10000);
  EXPECT_LE(cut.back() - cut.front(), 11 * 10000);
  EXPECT_GE(cut.back() - cut.front(), 10 * 10000);
  EXPECT_LT(cut.back(), all.back());

  for (const std::string& wrong : {std::string("+max_shown=-1"), std::string("+dump=w.vcd +dump_from=9 +dump_to=8"),
                                   std::string("+dump_from=3")}) {
    const CommandResult r = run_command("cd '" + dir_.string() + "' && ./run_icarus.sh " + wrong);
    EXPECT_EQ(r.status, 2) << wrong << "\n" << r.output;
    EXPECT_NE(r.output.find("\nerror: +"), std::string::npos) << wrong << "\n" << r.output;
    EXPECT_EQ(r.output.find(" passed, "), std::string::npos) << wrong << "\n" << r.output;
  }
}

// A frame cut short by +cycle_bound: its first mismatch says so, whatever else differs after it.
TEST_F(IcarusPackage, AFrameOverTheCycleBoundSaysSoFirst) {
  const std::string first = "first mismatch: frame.hex: the frame did not finish within the cycle bound";
  int cut = 0, without_result = 0;
  for (const int bound : {10, 40, 80, 120, 160, 240, 320}) {  // the start, and inside triangles
    const CommandResult r = replay("+cycle_bound=" + std::to_string(bound));
    if (last_line(r.output).find(", 0 failed") != std::string::npos) continue;  // the frame fits
    ++cut;
    EXPECT_NE(r.output.find(first + " (+cycle_bound=N) [cycle " + std::to_string(bound) + "]\n"), std::string::npos)
        << "+cycle_bound=" << bound << "\n" << r.output;
    // A fragment cut off before its depth-test result has no value to print (not all ones).
    EXPECT_EQ(r.output.find("0xffffffffffffffff"), std::string::npos) << "+cycle_bound=" << bound << "\n" << r.output;
    without_result += r.output.find("field pass: expected 0x1, actual: none (no depth-test result before the frame "
                                    "ended)") != std::string::npos;
  }
  EXPECT_GE(cut, 3);
  EXPECT_GE(without_result, 1);
}

// Mismatches come earliest first, by the cycle where they show, whatever file they are in.
TEST_F(IcarusPackage, MismatchesArePrintedEarliestFirst) {
  const Layouts layouts = make_layouts(small_profile());
  auto flip_lowest_bit = [&](const std::string& path, size_t index, const WordLayout& layout, const std::string& field) {
    std::vector<std::string> lines = split_lines(file_named(package_, path).content);
    const int digit = (layout.word_bits() - 1 - layout.field(field).lsb) / 4;
    char& c = lines.at(index)[size_t(digit)];
    c = "0123456789abcdef"[std::stoi(std::string(1, c), nullptr, 16) ^ 1];
    write_text(dir_ / path, join_lines(lines));
  };
  const size_t last_fragment = split_lines(file_named(package_, "fragments.hex").content).size() - 1;
  flip_lowest_bit("depth.hex", 0, layouts.depth, "depth");                          // after the frame
  flip_lowest_bit("fragments.hex", last_fragment, layouts.fragments, "z");           // the last fragment
  flip_lowest_bit("triangles.hex", 1, layouts.triangles, "walker_end");              // early
  const CommandResult r = replay();
  const std::vector<std::string> lines = split_lines(r.output);
  std::vector<std::string> shown;
  for (const std::string& line : lines)
    if (line.rfind("first mismatch: ", 0) == 0 || line.rfind("mismatch: ", 0) == 0) shown.push_back(line);
  ASSERT_EQ(shown.size(), 3u) << r.output;
  EXPECT_EQ(shown[0].rfind("first mismatch: triangles.hex vector 1 field walker_end:", 0), 0u) << r.output;
  EXPECT_EQ(shown[1].rfind("mismatch: fragments.hex vector " + std::to_string(last_fragment) + " field z:", 0), 0u)
      << r.output;
  EXPECT_EQ(shown[2].rfind("mismatch: depth.hex vector 0 field depth:", 0), 0u) << r.output;
  EXPECT_EQ(last_line(r.output), std::to_string(vector_count() - 3) + " passed, 3 failed") << r.output;
}

// A port with one more pipeline stage between the setup unit and the record FIFO: every record
// a cycle later. Cycle-exact mode fails it; functional mode passes it and reports its cycles.
TEST_F(IcarusPackage, AnExtraSetupStageFailsCycleExactAndPassesFunctional) {
  const std::string vvp = build_variant("extra_stage", [](std::string core) {
    const std::string declared = "  wire setup_valid;\n  wire [RECORD_BITS-1:0] setup_record;\n";
    const std::string outputs = "    .out_valid(setup_valid),\n    .out_record(setup_record), .out_texture(setup_texture));\n";
    const size_t d = core.find(declared), o = core.find(outputs);
    if (d == std::string::npos || o == std::string::npos) return core;
    core.replace(o, outputs.size(),
                 "    .out_valid(setup_valid_stage),\n    .out_record(setup_record_stage), .out_texture(setup_texture));\n"
                 "  reg setup_valid_late;\n  reg [RECORD_BITS-1:0] setup_record_late;\n"
                 "  always @(posedge clk) begin\n    setup_valid_late <= !rst && setup_valid_stage;\n"
                 "    setup_record_late <= setup_record_stage;\n  end\n"
                 "  assign setup_valid = setup_valid_late;\n  assign setup_record = setup_record_late;\n");
    core.insert(d + declared.size(), "  wire setup_valid_stage;\n  wire [RECORD_BITS-1:0] setup_record_stage;\n");
    return core;
  });
  const CommandResult exact = replay("", vvp);
  EXPECT_TRUE(std::regex_match(last_line(exact.output), std::regex("[0-9]+ passed, [1-9][0-9]* failed"))) << exact.output;
  EXPECT_NE(exact.output.find("first mismatch: "), std::string::npos) << exact.output;
  const CommandResult functional = replay("+functional", vvp);
  EXPECT_EQ(last_line(functional.output), std::to_string(vector_count()) + " passed, 0 failed") << functional.output;
  const std::smatch cycles = [&] {
    std::smatch m;
    std::regex_search(functional.output, m, std::regex("the frame took ([0-9]+) cycles \\(the model: ([0-9]+)\\)"));
    return m;
  }();
  ASSERT_EQ(cycles.size(), 3u) << functional.output;
  EXPECT_GT(std::stoll(cycles[1].str()), std::stoll(cycles[2].str())) << functional.output;
}

// A port that drops one fragment (the 41st the walker offers): functional mode reports one
// mismatch, naming the triangle and the pixel; what follows from it is counted apart.
TEST_F(IcarusPackage, ADroppedFragmentIsOneFunctionalMismatchNamingTriangleAndPixel) {
  const std::string vvp = build_variant("dropped_fragment", [](std::string core) {
    // The walker's fragments reach the z-buffer through two assigns (a core without the texture unit).
    const std::string wiring = "      assign frag_valid = walker_frag_valid;\n      assign walker_frag_ready = frag_ready;\n";
    const size_t w = core.find(wiring);
    if (w == std::string::npos) return core;
    core.replace(w, wiring.size(),
                 "      assign frag_valid = walker_frag_valid && !dropped;\n"
                 "      assign walker_frag_ready = frag_ready || dropped;\n");
    const std::string anchor = "  scanline_walker #(";
    core.insert(core.find(anchor),
                "  reg [31:0] offered_q;\n  wire dropped = walker_frag_valid && offered_q == 32'd40;\n"
                "  always @(posedge clk)\n    if (rst) offered_q <= 32'd0;\n"
                "    else if (walker_frag_valid && walker_frag_ready) offered_q <= offered_q + 32'd1;\n");
    return core;
  });
  // The 41st expected fragment, read from the package's words (not from the testbench).
  const Layouts layouts = make_layouts(small_profile());
  const std::vector<int64_t> dropped = layouts.fragments.parse(split_lines(file_named(package_, "fragments.hex").content).at(40));
  const std::string named = "fragments.hex vector 40: missing: triangle " + std::to_string(dropped[0]) + ", pixel (" +
                            std::to_string(dropped[2]) + ", " + std::to_string(dropped[3]) + ")";
  const CommandResult functional = replay("+functional", vvp);
  EXPECT_NE(functional.output.find("first mismatch: " + named), std::string::npos) << named << "\n" << functional.output;
  EXPECT_EQ(functional.output.find("\nmismatch: "), std::string::npos) << functional.output;
  EXPECT_TRUE(std::regex_match(last_line(functional.output), std::regex("[0-9]+ passed, 1 failed"))) << functional.output;
  EXPECT_TRUE(std::regex_search(functional.output, std::regex("; [1-9][0-9]* vectors differ only as a consequence")))
      << functional.output;
  const CommandResult exact = replay("", vvp);
  EXPECT_NE(exact.output.find(named), std::string::npos) << exact.output;
}

// A package of rastersim_core with 30 % back-pressure: the memory model on its memory port refuses
// reads in the model's stall cycles, so the cycle-exact run passes; the same package with another
// stall seed in its parameter file fails (the pattern is what makes the cycles).
TEST(IcarusCorePackage, BackPressureFromTheModelsStallPatternStaysCycleExact) {
  Profile p = small_profile();
  p.memory_stall_percent = 30;
  p.memory_stall_seed = 5;
  PackageOptions options;
  EXPECT_THROW(build_package(p, suite_triangles("depth", p), Source{"suite", "depth", 0, 0, "", ""}, options), InputError);
  options.external_memory = true;
  const Package package = build_package(p, suite_triangles("depth", p), Source{"suite", "depth", 0, 0, "", ""}, options);
  const Json manifest = Json::parse(file_named(package, "manifest.json").content);
  EXPECT_EQ(manifest["rtl"]["top"], "rastersim_core");
  const std::string params = file_named(package, "rastersim_vectors_params.vh").content;
  EXPECT_NE(params.find("`define RS_EXTERNAL_MEMORY"), std::string::npos) << params;
  const Layouts layouts = make_layouts(p);
  const std::vector<int64_t> frame = layouts.frame.parse(split_lines(file_named(package, "frame.hex").content).at(0));
  const std::vector<Field>& fields = layouts.frame.fields();
  const size_t walker_stall = size_t(std::find_if(fields.begin(), fields.end(), [](const Field& f) { return f.name == "walker_stall"; }) - fields.begin());
  EXPECT_GT(frame.at(walker_stall), 0) << "the stall pattern refused no read the walker offered";

  TempDir dir;
  const fs::path pkg = dir.path() / "pkg";
  write_package(package, pkg.string(), false);
  const CommandResult run = run_command("'" + (pkg / "run_icarus.sh").string() + "'");
  EXPECT_EQ(run.status, 0) << run.output;
  EXPECT_TRUE(std::regex_match(last_line(run.output), std::regex("[0-9]+ passed, 0 failed"))) << run.output;

  std::string other = read_text(pkg / "rastersim_vectors_params.vh");
  const std::string seed = "localparam integer MEMORY_STALL_SEED = 5;";
  ASSERT_NE(other.find(seed), std::string::npos) << other;
  other.replace(other.find(seed), seed.size(), "localparam integer MEMORY_STALL_SEED = 6;");
  write_text(pkg / "rastersim_vectors_params.vh", other);
  const CommandResult built = run_command("cd '" + pkg.string() + "' && " + RASTERSIM_IVERILOG +
                                          " -g2012 -I . -I rtl -s rastersim_vectors_tb -o tb.vvp rastersim_vectors_tb.v "
                                          "rastersim_memory_model.v rtl/*.sv && " + RASTERSIM_VVP + " -n tb.vvp");
  EXPECT_TRUE(std::regex_match(last_line(built.output), std::regex("[0-9]+ passed, [1-9][0-9]* failed"))) << built.output;
  EXPECT_NE(built.output.find("field cycle: "), std::string::npos) << built.output;
}

// The board self-test in Icarus: PASS with the package's CRCs (computed here from depth.hex and
// color.hex, not by the package writer), FAIL when one expected CRC word changes; and the run
// script refuses the changed selftest.hex before simulating (manifest CRC-32).
TEST(IcarusSelftest, PassesWithThePackagesCrcsAndFailsWhenOneChanges) {
  const Profile p = small_profile();
  const Package package = small_package();
  // The expected CRCs from the expected memories: depth words as 3 bytes (N = 24), colour as 3.
  std::string depth_bytes, color_bytes;
  for (const std::string& line : split_lines(file_named(package, "depth.hex").content))
    for (int b = 0; b < (p.z_bits + 7) / 8; ++b) depth_bytes += char((std::stoul(line, nullptr, 16) >> (8 * b)) & 0xFF);
  for (const std::string& line : split_lines(file_named(package, "color.hex").content))
    for (int b = 0; b < 3; ++b) color_bytes += char((std::stoul(line, nullptr, 16) >> (8 * b)) & 0xFF);
  char expected[32];
  std::snprintf(expected, sizeof expected, "%08x\n%08x\n", crc32(depth_bytes), crc32(color_bytes));
  EXPECT_EQ(file_named(package, "selftest.hex").content, expected);

  TempDir dir;
  const fs::path pkg = dir.path() / "pkg";
  write_package(package, pkg.string(), false);
  const CommandResult passed = run_command("'" + (pkg / "run_selftest_icarus.sh").string() + "'");
  EXPECT_EQ(passed.status, 0) << passed.output;
  EXPECT_EQ(last_line(passed.output), "selftest: PASS") << passed.output;
  EXPECT_NE(passed.output.find(std::string("depth CRC 0x") + std::string(expected, 8)), std::string::npos) << passed.output;

  for (int line = 0; line < 2; ++line) {
    std::vector<std::string> crcs = split_lines(file_named(package, "selftest.hex").content);
    crcs[size_t(line)][7] = crcs[size_t(line)][7] == '0' ? '1' : '0';
    write_text(pkg / "selftest.hex", join_lines(crcs));
    const CommandResult refused = run_command("'" + (pkg / "run_selftest_icarus.sh").string() + "'");
    EXPECT_EQ(refused.status, 2) << refused.output;
    EXPECT_NE(refused.output.find("check_manifest: selftest.hex: "), std::string::npos) << refused.output;
    const CommandResult failed = run_command("cd '" + pkg.string() + "' && " + RASTERSIM_IVERILOG +
                                             " -g2012 -I . -I rtl -s rastersim_selftest_sim -o st.vvp "
                                             "rastersim_selftest.v rtl/*.sv && " + RASTERSIM_VVP + " -n st.vvp");
    EXPECT_EQ(last_line(failed.output), "selftest: FAIL") << line << "\n" << failed.output;
  }
}

// A flipped digit in any file of a package, the manifest included, is caught by check_manifest.py
// (which the run scripts call before anything else) naming that file.
TEST(PackageCheck, AFlippedDigitInAnyFileIsCaughtBeforeTheRun) {
  TempDir dir;
  const fs::path pkg = dir.path() / "pkg";
  const Package package = small_package();
  write_package(package, pkg.string(), false);
  const CommandResult clean = run_command("python3 '" + (pkg / "check_manifest.py").string() + "'");
  ASSERT_EQ(clean.status, 0) << clean.output;
  int flipped = 0;
  for (const PackageFile& f : package.files) {
    std::string text = f.content;
    // The last digit of the file (a hex digit in .hex files, a digit of a number elsewhere).
    const size_t at = text.find_last_of("0123456789");
    if (at == std::string::npos) continue;
    text[at] = text[at] == '0' ? '1' : '0';
    write_text(pkg / f.path, text);
    const CommandResult r = run_command("python3 '" + (pkg / "check_manifest.py").string() + "'");
    // (The checker itself, changed, still names itself; its exit code is then its own business.)
    if (f.path != "check_manifest.py") {
      EXPECT_EQ(r.status, 2) << f.path << "\n" << r.output;
    }
    EXPECT_NE(r.output.find("check_manifest: " + f.path + ": "), std::string::npos) << f.path << "\n" << r.output;
    write_text(pkg / f.path, f.content);
    ++flipped;
  }
  EXPECT_GE(flipped, 20);
  EXPECT_EQ(run_command("python3 '" + (pkg / "check_manifest.py").string() + "'").status, 0);
}

// A changed commands.hex (two commands swapped, the expected outputs left alone) once passed the
// manifest unnoticed: the run scripts now check every file's CRC-32 first and refuse (exit 2). The
// testbench itself, run without the check, reports the mismatches.
TEST_F(IcarusPackage, SwappingTwoCommandsFailsAndTheScriptSaysSo) {
  std::vector<std::string> commands = split_lines(file_named(package_, "commands.hex").content);
  ASSERT_GT(commands.size(), 5u);
  ASSERT_NE(commands[1], commands[5]);
  std::swap(commands[1], commands[5]);
  write_text(dir_ / "commands.hex", join_lines(commands));
  const CommandResult checked = run_command("'" + (dir_ / "run_icarus.sh").string() + "'");
  EXPECT_EQ(checked.status, 2) << checked.output;
  EXPECT_NE(checked.output.find("check_manifest: commands.hex: "), std::string::npos) << checked.output;
  EXPECT_NE(checked.output.find("changed since the package was made"), std::string::npos) << checked.output;
  const CommandResult r = replay();
  EXPECT_TRUE(std::regex_search(r.output, std::regex("first mismatch: [a-z]+\\.hex vector [0-9]+ field [a-z0-9_]+: "
                                                     "expected 0x[0-9a-f]+, actual 0x[0-9a-f]+")))
      << r.output;
  EXPECT_TRUE(std::regex_match(last_line(r.output), std::regex("[0-9]+ passed, [1-9][0-9]* failed"))) << r.output;

  std::swap(commands[1], commands[5]);
  write_text(dir_ / "commands.hex", join_lines(commands));
  const CommandResult restored = run_command("'" + (dir_ / "run_icarus.sh").string() + "'");
  EXPECT_EQ(restored.status, 0) << restored.output;
}

#endif

// Builds the package's testbench with Icarus in its folder (bypassing the manifest check, so that a
// test can change a file) and returns the run's output.
std::string compile_and_run(const fs::path& pkg) {
  return run_command("cd '" + pkg.string() + "' && " + RASTERSIM_IVERILOG +
                     " -g2012 -I . -I rtl -s rastersim_vectors_tb -o tb.vvp rastersim_vectors_tb.v "
                     "rastersim_memory_model.v rtl/*.sv && " + RASTERSIM_VVP + " -n tb.vvp")
      .output;
}

// Replaces the one occurrence of `from` in a package's file by `to`.
void edit_file(const fs::path& file, const std::string& from, const std::string& to) {
  std::string text = read_text(file);
  const size_t at = text.find(from);
  ASSERT_NE(at, std::string::npos) << from << " not in " << file;
  text.replace(at, from.size(), to);
  write_text(file, text);
}

// The floating-point depth word and the depth bias through the package's testbench and its board
// self-test: both pass; the testbench fails when the bias it drives is not the profile's.
TEST(IcarusDepthPackage, TheFloatingPointWordAndTheBiasPassAndAWrongBiasFails) {
  Profile p = small_profile();
  p.depth_func = DepthFunc::Greater;
  p.depth_clear = 0;
  p.depth_exponent_bits = 3;  // Np = 21 + 7 = 28 plane bits behind a 24-bit word
  p.depth_bias_constant = -200000;  // far more than the word's truncation (at most 7 of the 28 bits)
  p.depth_bias_slope = 24;          // 1.5
  const Package package = build_package(p, suite_triangles("depth", p), Source{"suite", "depth", 0, 0, "", ""}, {});
  const Layouts layouts = make_layouts(p);
  EXPECT_EQ(layouts.commands.field("z0").bits, 28);
  const std::string params = file_named(package, "rastersim_vectors_params.vh").content;
  EXPECT_NE(params.find("localparam [32:0] CFG_DEPTH_BIAS_CONSTANT = 33'd8589734592;"), std::string::npos) << params;
  EXPECT_NE(params.find("localparam [7:0] CFG_DEPTH_BIAS_SLOPE = 8'd24;"), std::string::npos) << params;

  TempDir dir;
  const fs::path pkg = dir.path() / "pkg";
  write_package(package, pkg.string(), false);
  const CommandResult run = run_command("'" + (pkg / "run_icarus.sh").string() + "'");
  EXPECT_TRUE(std::regex_match(last_line(run.output), std::regex("[0-9]+ passed, 0 failed"))) << run.output;
  const CommandResult selftest = run_command("'" + (pkg / "run_selftest_icarus.sh").string() + "'");
  EXPECT_EQ(last_line(selftest.output), "selftest: PASS") << selftest.output;

  edit_file(pkg / "rastersim_vectors_params.vh", "CFG_DEPTH_BIAS_CONSTANT = 33'd8589734592;",
            "CFG_DEPTH_BIAS_CONSTANT = 33'd0;");
  const std::string wrong = compile_and_run(pkg);
  EXPECT_TRUE(std::regex_match(last_line(wrong), std::regex("[0-9]+ passed, [1-9][0-9]* failed"))) << wrong;
  EXPECT_NE(wrong.find("fragments.hex vector "), std::string::npos) << wrong;
  EXPECT_NE(wrong.find(" field z: "), std::string::npos) << wrong;
}

// A frame of textured triangles (cosim's generator) with a texture of distinct texels, bilinear,
// under the texture memory's stall pattern: cycle-exact through rastersim_top and through
// rastersim_core with the texture memory beside it. Another stall seed fails on cycles; a changed
// texel fails on colours.
TEST(IcarusTexturedPackage, TheTextureUnitStaysCycleExactUnderItsStallPattern) {
  Profile p;
  p.width = 32;
  p.height = 24;
  p.texture_unit = true;
  p.texture_latency = 3;
  p.texture_stall_percent = 30;
  p.texture_stall_seed = 4;
  p.memory_latency = 2;
  const rtl::CosimCase frame = rtl::random_case(p, 7, 30);
  std::vector<uint32_t> texels;
  for (uint32_t a = 0; a < 8 * 4; ++a) texels.push_back(0x102030u + a * 0x050709u);
  TextureBinding texture;
  texture.texture = std::make_shared<const Texture>(3, 2, texels);
  texture.filter = TextureFilter::Bilinear;
  const Source source{"random", "", 30, 7, "", ""};
  const Package package = build_package(p, frame.triangles, source, {}, texture);
  EXPECT_EQ(file_named(package, "texture.hex").content.substr(0, 14), "102030\n152739\n");
  EXPECT_THROW(file_named(package, "selftest.hex"), std::runtime_error);  // no board self-test
  const Layouts layouts = make_layouts(p);
  const std::vector<Field>& command_fields = layouts.commands.fields();
  const size_t textured_field = size_t(
      std::find_if(command_fields.begin(), command_fields.end(), [](const Field& f) { return f.name == "textured"; }) -
      command_fields.begin());
  int64_t textured = 0;
  for (const std::string& line : split_lines(file_named(package, "commands.hex").content))
    textured += layouts.commands.parse(line).at(textured_field);
  EXPECT_GT(textured, 10);
  const std::vector<int64_t> counters = layouts.frame.parse(split_lines(file_named(package, "frame.hex").content).at(0));
  EXPECT_GT(counters.at(18), 0) << "the stall pattern held no texture read";  // texture_stall
  EXPECT_GT(counters.at(17), 0);                                                 // texture_busy

  TempDir dir;
  const fs::path pkg = dir.path() / "pkg";
  write_package(package, pkg.string(), false);
  const CommandResult run = run_command("'" + (pkg / "run_icarus.sh").string() + "'");
  EXPECT_TRUE(std::regex_match(last_line(run.output), std::regex("[0-9]+ passed, 0 failed"))) << run.output;

  edit_file(pkg / "rastersim_vectors_params.vh", "TEXTURE_STALL_SEED = 4;", "TEXTURE_STALL_SEED = 5;");
  const std::string other_seed = compile_and_run(pkg);
  EXPECT_TRUE(std::regex_match(last_line(other_seed), std::regex("[0-9]+ passed, [1-9][0-9]* failed"))) << other_seed;
  EXPECT_NE(other_seed.find(" field cycle: "), std::string::npos) << other_seed;
  edit_file(pkg / "rastersim_vectors_params.vh", "TEXTURE_STALL_SEED = 5;", "TEXTURE_STALL_SEED = 4;");
  edit_file(pkg / "texture.hex", "152739\n", "152738\n");
  const std::string other_texel = compile_and_run(pkg);
  EXPECT_TRUE(std::regex_match(last_line(other_texel), std::regex("[0-9]+ passed, [1-9][0-9]* failed"))) << other_texel;
  EXPECT_NE(other_texel.find(" field rgb: "), std::string::npos) << other_texel;

  PackageOptions core;
  core.external_memory = true;
  const fs::path core_pkg = dir.path() / "core";
  write_package(build_package(p, frame.triangles, source, core, texture), core_pkg.string(), false);
  const CommandResult core_run = run_command("'" + (core_pkg / "run_icarus.sh").string() + "'");
  EXPECT_TRUE(std::regex_match(last_line(core_run.output), std::regex("[0-9]+ passed, 0 failed"))) << core_run.output;
}

}  // namespace
}  // namespace rastersim::vectors
