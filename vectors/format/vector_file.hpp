// texunit vector files: a simulator-neutral text format (specified in vectors/README.md).
//
//   # texunit-vectors 1
//   # block: reciprocal
//   # set: random
//   # seed: 1
//   # fields: q:in:s24.16 mant:out:u25.24 shift:out:u5.0 flag:out:u1.0 ref:ref:f64
//   0000a3 0155555 05 0 3fd5555555555555
//
// Every data line holds one hex field per declared field, in order. Fixed-point fields carry the
// raw code (two's complement for s, at most ceil(W/4) digits, value < 2^W); f64 fields carry the
// 16-digit IEEE-754 bit pattern, so the reference value round-trips exactly.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <stdexcept>
#include <string>
#include <vector>

namespace tu::vec {

enum class Role { In, Out, Ref };

struct FieldFormat {
  bool is_f64 = false;
  bool is_signed = false;
  int w = 0;  // word length (64 for f64)
  int f = 0;  // fraction bits
  std::string str() const;
  static FieldFormat parse(const std::string& s);  // throws std::invalid_argument
};

struct Field {
  std::string name;
  Role role = Role::In;
  FieldFormat fmt;
};

struct VectorFile {
  std::string block;
  std::string set;
  uint64_t seed = 0;
  // `--shard K/N`: the file holds rows [first_vector, ...) of the whole set (header `# shard: K/N
  // first F`); empty shard: the whole set.
  std::string shard;
  uint64_t first_vector = 0;
  std::vector<Field> fields;
  std::vector<std::vector<uint64_t>> rows;  // one uint64 per field (raw code or f64 bits)

  // Indices of the fields with a given role, in declaration order.
  std::vector<int> indices(Role r) const;
  int index_of(const std::string& name) const;  // -1 when absent
};

// A malformed file: the message is "FILE:LINE: reason" (control bytes quoted from the file
// escaped, tu::printable).
struct FormatError : std::runtime_error {
  explicit FormatError(const std::string& what);
};

VectorFile read(const std::string& path);                       // throws FormatError
VectorFile parse(const std::string& text, const std::string& name);  // same, from memory
std::string serialise(const VectorFile& v);
void serialise(const VectorFile& v, std::ostream& os);
// Writes atomically (temporary file + rename): a failed run leaves no partial output.
void write(const VectorFile& v, const std::string& path);

uint64_t f64_bits(double x);
double bits_f64(uint64_t b);
// Sign-extend a raw W-bit code.
int64_t sext(uint64_t raw, int w);

}  // namespace tu::vec
