// Shared by the libFuzzer targets of this folder (docs/robustness.md). A target returns normally for
// every input the product handles: accepted, or refused with an InputError that names the file and
// the line. Anything else is a finding: an uncaught exception (WidthOverflow, logic_error, ...), a
// sanitizer report, or a broken invariant reported here with FUZZ_REQUIRE (abort, so libFuzzer keeps
// the input as a crash artifact).
#pragma once

#include <cstdio>
#include <cstdlib>
#include <string>

#include "model/profile.h"

namespace rastersim::fuzz {

[[noreturn]] inline void fail(const char* file, int line, const char* condition, const std::string& detail) {
  std::fprintf(stderr, "\n%s:%d: invariant broken: %s\n  %s\n", file, line, condition, detail.c_str());
  std::abort();
}

#define FUZZ_REQUIRE(condition, detail)                                              \
  do {                                                                               \
    if (!(condition)) ::rastersim::fuzz::fail(__FILE__, __LINE__, #condition, detail); \
  } while (0)

// An InputError's message must locate the problem: "<file_name>:<line>: <problem>" with a line
// number >= 1 when `needs_line`, else at least "<file_name>: <problem>".
inline void require_located_message(const std::string& message, const std::string& file_name, bool needs_line) {
  const std::string prefix = file_name + ":";
  FUZZ_REQUIRE(message.compare(0, prefix.size(), prefix) == 0, "message does not start with the file name: " + message);
  size_t at = prefix.size();
  size_t digits = 0;
  while (at < message.size() && message[at] >= '0' && message[at] <= '9') ++at, ++digits;
  if (needs_line) FUZZ_REQUIRE(digits > 0 && message[prefix.size()] != '0', "message has no line number: " + message);
  if (digits > 0) FUZZ_REQUIRE(at < message.size() && message[at] == ':', "line number not followed by ':': " + message);
  FUZZ_REQUIRE(message.size() > at + 2, "message names no problem: " + message);
}

}  // namespace rastersim::fuzz
