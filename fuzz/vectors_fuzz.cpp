// Fuzz target: the vector-file reader (vectors/format/vector_file.cpp). Any input either parses
// or is a FormatError naming the file and line; what parses round-trips through serialise().
#include <cstdint>
#include <string>

#include "vector_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  tu::vec::VectorFile v;
  try {
    v = tu::vec::parse(text, "fuzz.vec");
  } catch (const tu::vec::FormatError& e) {
    if (std::string(e.what()).rfind("fuzz.vec:", 0) != 0) __builtin_trap();
    return 0;
  }
  const std::string once = tu::vec::serialise(v);
  const auto back = tu::vec::parse(once, "again.vec");
  if (tu::vec::serialise(back) != once || back.rows != v.rows || back.seed != v.seed) __builtin_trap();
  return 0;
}
