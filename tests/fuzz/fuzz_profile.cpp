// Fuzz target: the JSON profile parser (model/profile.cpp load_profile_text) as `--profile FILE`
// uses it. A profile that loads and validates must derive its widths, and profile_to_json must load
// back to the same profile.
#include <cstdint>
#include <string>

#include "model/input_error.h"
#include "model/profile.h"
#include "model/widths.h"
#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace rastersim;
  const std::string text(reinterpret_cast<const char*>(data), size);
  Profile profile;
  try {
    load_profile_text(profile, text, "fuzz.json");
  } catch (const InputError& e) {
    fuzz::require_located_message(e.what(), "fuzz.json", true);
    return 0;
  }
  if (!validate(profile).empty()) return 0;  // the CLI reports these and stops
  const Widths widths = derive_widths(profile);
  FUZZ_REQUIRE(widths.z_reg_bits <= 63 && widths.divider_bits <= 126, "a valid profile outgrows the model's storage");
  const std::string written = profile_to_json(profile);
  Profile reread;
  load_profile_text(reread, written, "written.json");
  FUZZ_REQUIRE(profile_to_json(reread) == written, "profile_to_json does not load back to the same profile:\n" + written);
  return 0;
}
