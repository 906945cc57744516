// Fuzz target for one registry block (TU_FUZZ_BLOCK): the input bytes are its in-field codes
// (each field takes ceil(W/8) bytes, little endian, masked to its W bits; missing bytes are 0),
// fed to the C model, the float reference and the error metric. Every code a field can hold must
// be defined (no sanitizer report); a model may reject an illegal code with
// std::invalid_argument (documented per block); every output code fits its declared field.
#include <cstdint>
#include <stdexcept>

#include "block.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const tu::blocks::Block& b = tu::blocks::find(TU_FUZZ_BLOCK);
  tu::blocks::Row in, out_w;
  size_t at = 0;
  for (const auto& f : b.fields) {
    if (f.role == tu::vec::Role::Out) out_w.push_back(static_cast<uint64_t>(f.fmt.w));
    if (f.role != tu::vec::Role::In) continue;
    uint64_t x = 0;
    for (int k = 0; k < (f.fmt.w + 7) / 8; ++k, ++at)
      if (at < size) x |= uint64_t(data[at]) << (8 * k);
    if (f.fmt.w < 64) x &= (uint64_t(1) << f.fmt.w) - 1;
    in.push_back(x);
  }
  try {
    const auto out = b.model(in);
    const auto ref = b.ref(in);
    (void)b.error(in, out, ref);
    if (out.size() != out_w.size()) __builtin_trap();
    for (size_t i = 0; i < out.size(); ++i)
      if (out_w[i] < 64 && (out[i] >> out_w[i]) != 0) __builtin_trap();  // output exceeds its field
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
