// The hardware profile: the one source of truth for model, RTL and vectors (docs/formats.md "Profile").
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace rastersim {

enum class DepthFunc { Never, Less, Equal, LEqual, Greater, NotEqual, GEqual, Always };
enum class CullMode { None, Back, Front };
enum class FrontFace { CCW, CW };
// bbox: every pixel of the screen-clipped bounding box is a candidate, one per clock.
// span: per row the edges' exact crossings bound the span; empty pixels cost no cycles.
enum class Traversal { BBox, Span };
enum class Shading { Flat, Gouraud };
// What the 3D front end puts in the depth plane: the projected z, or near / w (docs/arithmetic.md
// section 6).
enum class DepthBuffer { Z, InverseW };
// Conventions a design may choose differently (docs/arithmetic.md section 7). The first value of
// each is rastersim's own.
// Where pixel (i, j) is sampled: its centre (i + 1/2, j + 1/2) or its corner (i, j).
enum class PixelCenter { Half, Corner };
// Which edges own the samples that lie exactly on them: a horizontal edge is owned when the
// interior lies below it (top) or above it (bottom), another edge when the interior lies to its
// right (left) or to its left (right). y points down.
enum class FillRule { TopLeft, TopRight, BottomLeft, BottomRight };
// How a vertex coordinate x becomes X subpixels: floor(x 2^S + 1/2), ties to even, floor(x 2^S),
// or toward zero.
enum class VertexSnap { Nearest, NearestEven, Floor, TowardZero };
// How a plane register value V with F fraction bits becomes an integer output: floor(V / 2^F + 1/2)
// or floor(V / 2^F).
enum class Rounding { Nearest, Truncate };

constexpr int kMaxSetupFifoDepth = 16;  // the RTL's MAX_SETUP_FIFO_DEPTH default
constexpr int kMaxMemoryLatency = 64, kMaxTextureLatency = 64;  // memory_latency, texture_latency
constexpr int kMinSetupInterval = 2, kMaxSetupInterval = 64;  // the pipelined setup unit's range

// Np, the depth plane's bits for a depth word of z_bits with exponent_bits (docs/arithmetic.md
// section 6): z_bits for the fixed-point word (0).
constexpr int depth_plane_bits(int z_bits, int exponent_bits) {
  return exponent_bits == 0 ? z_bits : z_bits - exponent_bits + (1 << exponent_bits) - 1;
}

struct Profile {
  int width = 640;            // pixels, 1..4096
  int height = 480;           // pixels, 1..4096
  int subpixel_bits = 4;      // S, 1..8
  int z_bits = 24;            // N, 16..32
  int z_guard_bits = 0;       // F, fraction bits of the plane registers; 0 = derive (proven minimum)
  DepthFunc depth_func = DepthFunc::Less;
  bool depth_write = true;
  int64_t depth_clear = -1;   // -1 = 2^N - 1, or 0 with depth_buffer inverse_w
  DepthBuffer depth_buffer = DepthBuffer::Z;
  // Ne: 0 = the fixed-point depth word; 1..4 = an unsigned floating-point word of z_bits bits with
  // Ne exponent bits, the depth plane then depth_plane_bits() wide (docs/arithmetic.md section 6).
  int depth_exponent_bits = 0;
  int64_t depth_bias_constant = 0;  // c, depth plane LSBs, |c| < 2^depth_plane_bits()
  int depth_bias_slope = 0;         // f = 16 x the slope factor: s4.4, -128..127
  CullMode cull = CullMode::None;
  FrontFace front_face = FrontFace::CCW;
  Traversal traversal = Traversal::Span;
  Shading shading = Shading::Gouraud;
  int memory_latency = 2;     // cycles from a z-buffer read request to its data, 1..64
  // Back-pressure of the z-buffer memory: it refuses reads in about this percentage of the cycles,
  // 0..90, in a pattern fixed by the seed (zbuffer_memory.h). 0: never (the on-chip memory).
  int memory_stall_percent = 0;
  int memory_stall_seed = 1;  // 0..2^31-1
  // Setup records that may be on their way to the walker: accepted by the setup unit (and not
  // rejected) but not yet loaded by the walker, 1..16. 1: the walker must take a record before the
  // setup unit accepts the next triangle. docs/cycle-model.md.
  int setup_fifo_depth = 8;
  // Initiation interval of the setup unit: 0 = the serial unit (one triangle at a time through one
  // shared datapath, about 1,500 cycles per drawn triangle); 2..64 = the pipelined unit, which accepts a
  // triangle every I cycles at best. docs/cycle-model.md.
  int setup_interval = 4;
  // The texture unit between the walker and the z-buffer (docs/cycle-model.md "Texture unit"): a
  // build option of the hardware; without it a triangle's texture coordinates are ignored.
  bool texture_unit = false;
  bool perspective = true;        // false: texture coordinates interpolated affinely (every w equal)
  int texture_latency = 2;        // cycles from a texture read request to its texels, 1..64
  int texture_stall_percent = 0;  // texture memory back-pressure, 0..90, as memory_stall_percent
  int texture_stall_seed = 1;     // 0..2^31-1
  PixelCenter pixel_center = PixelCenter::Half;
  FillRule fill_rule = FillRule::TopLeft;
  VertexSnap vertex_snap = VertexSnap::Nearest;
  Rounding depth_rounding = Rounding::Nearest;
  Rounding color_rounding = Rounding::Nearest;

  uint32_t depth_max() const { return uint32_t((uint64_t(1) << z_bits) - 1); }
  uint32_t depth_clear_value() const {
    return depth_clear >= 0 ? uint32_t(depth_clear) : depth_buffer == DepthBuffer::InverseW ? 0 : depth_max();
  }
  // Np: the depth plane's bits (z_bits with the fixed-point word).
  int depth_plane_bits() const { return rastersim::depth_plane_bits(z_bits, depth_exponent_bits); }
  bool depth_biased() const { return depth_bias_constant != 0 || depth_bias_slope != 0; }
  // The sample point's offset from pixel i's left (top) edge, in subpixels: 2^(S-1) or 0.
  int64_t sample_offset() const { return pixel_center == PixelCenter::Half ? int64_t(1) << (subpixel_bits - 1) : 0; }
};

// Every error found, each a sentence naming the key; empty when the profile is valid.
std::vector<std::string> validate(const Profile& profile);

// Names as they appear in JSON and on the command line.
const char* to_string(DepthFunc v);
const char* to_string(CullMode v);
const char* to_string(FrontFace v);
const char* to_string(Traversal v);
const char* to_string(Shading v);
const char* to_string(DepthBuffer v);
const char* to_string(PixelCenter v);
const char* to_string(FillRule v);
const char* to_string(VertexSnap v);
const char* to_string(Rounding v);
std::optional<DepthFunc> parse_depth_func(const std::string& s);
std::optional<CullMode> parse_cull(const std::string& s);
std::optional<FrontFace> parse_front_face(const std::string& s);
std::optional<Traversal> parse_traversal(const std::string& s);
std::optional<Shading> parse_shading(const std::string& s);
std::optional<DepthBuffer> parse_depth_buffer(const std::string& s);

// The profile table: one row per key, the only place a key is defined. Flags, JSON reading and
// writing, validation, --help and docs/formats.md's key table are all made from it.
enum class KeyType {
  Integer,     // a JSON integer; `word`, when set, is a second spelling of one value ("auto", "max")
  Boolean,     // true / false
  Choice,      // one of `choices`, stored as the enum's value
  Sixteenths,  // a decimal multiple of 1/16, stored as sixteenths
};
// Where a key lives in the RTL (docs/rtl.md "The profile in the RTL").
enum class RtlPlace {
  None,       // outside the core: the front end, the memory models of the harness
  Port,       // a cfg_* input of rastersim_core (`rtl_name`), sampled during reset
  Parameter,  // a build parameter of rastersim_core (`rtl_name`; core_parameters() maps it)
  Both,       // a cfg_* input whose largest value (or whose presence) is a build parameter:
              // `rtl_name` is "cfg_port, PARAMETER"
};
// How a built core's parameter must relate to the profile's value to run it (core_mismatch()):
// Equal; Bound, the core may hold more (a largest latency, a FIFO's size, an option the profile
// leaves unused; every Both row); Guard, the same resolved plane fraction bits (0 derives them).
enum class CoreFit { Equal, Bound, Guard };
struct ProfileKey {
  const char* key;  // JSON key; the flag is --key with '-' for '_'
  KeyType type;
  int64_t min, max;            // the stored value's range (validate())
  const char* word;            // Integer: another spelling of `word_value`, or nullptr
  int64_t word_value;
  std::vector<const char*> choices;  // Choice: the names, in the enum's order
  const char* values;          // docs/formats.md "values": what a user may write
  const char* meaning;         // docs/formats.md "meaning", also the flag's help (links made plain)
  RtlPlace place;
  const char* rtl_name;        // the port or parameter(s), "" for None
  int64_t (*get)(const Profile&);
  void (*set)(Profile&, int64_t);
  // What profile_to_json writes when it is not get(): depth_clear's resolved value. nullptr: get().
  int64_t (*written)(const Profile&) = nullptr;
  // Parameter and Both rows, rastersim_core's build parameter (model/core_parameters.h). Its value
  // for the profile, `largest` asking for the largest core a Both row's run-time input allows;
  // nullptr: get() (a Both row: `max` when largest).
  int64_t (*core_value)(const Profile&, bool largest) = nullptr;
  CoreFit core_fit = CoreFit::Equal;  // a Both row's is Bound
};

// The keys, in the order they are documented and written.
const std::vector<ProfileKey>& profile_table();
// The row of `key`, or nullptr.
const ProfileKey* find_profile_key(const std::string& key);
// The keys' names in table order.
const std::vector<std::string>& profile_keys();
// A stored value as a user writes it ("auto", "lequal", "true", "1.5", "640").
std::string key_value_text(const ProfileKey& row, int64_t value);
// The --help text of a key: its meaning (links made plain), values and default.
std::string key_help(const ProfileKey& row);
// docs/formats.md's key table (markdown), made from the table.
std::string profile_table_markdown();

// Sets one key from its textual value (a flag or a JSON scalar rendered as text). Returns an error
// sentence, or an empty string on success.
std::string set_profile_key(Profile& profile, const std::string& key, const std::string& value);

// A profile file is a few hundred bytes; anything beyond this is not one.
constexpr size_t kMaxProfileBytes = size_t(1) << 20;
// Reads a JSON profile file over `profile`. Throws InputError naming file, line and problem.
void load_profile_file(Profile& profile, const std::string& path);
// The same for the JSON text of a profile; `file_name` names it in errors.
void load_profile_text(Profile& profile, const std::string& text, const std::string& file_name);

// A named set of convention keys for an API whose specification states them exactly
// (docs/arithmetic.md section 7): `--conventions NAME` sets them, before the flags that name a
// key themselves.
struct ConventionPreset {
  const char* name;
  const char* source;  // what states them
  std::vector<std::pair<const char*, const char*>> keys;  // key, value
};
const std::vector<ConventionPreset>& convention_presets();
const ConventionPreset* find_convention_preset(const std::string& name);

// The conventions of docs/arithmetic.md section 7 that differ from the defaults, as
// "pixel_center corner, fill_rule top_right"; empty with rastersim's own.
std::string conventions_text(const Profile& profile);

// The profile as a JSON object text (all keys, resolved values).
std::string profile_to_json(const Profile& profile, int indent = 2);

}  // namespace rastersim
