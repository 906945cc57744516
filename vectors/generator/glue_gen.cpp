#include "glue_gen.hpp"

#include <algorithm>
#include <cctype>
#include <sstream>
#include <stdexcept>

#include "block.hpp"

namespace tu::blocks {

namespace {
bool is_identifier(const std::string& s) {
  if (s.empty() || std::isdigit(static_cast<unsigned char>(s[0]))) return false;
  for (char c : s)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') return false;
  return true;
}
}  // namespace

std::string generated_glue() {
  std::ostringstream os;
  os << "// Generated at build time by tu_gen_glue (vectors/tools/gen_glue_main.cpp) from the vector blocks' field lists (vectors/generator/*_block.cpp):\n"
        "// do not edit. For block B, drive_B(d, in) puts in-field k of a vector row on port <name>_i and\n"
        "// sample_B(d) reads out-field k from port <name>_o, in the file's field order. Templates: a block\n"
        "// whose RTL does not follow the naming (e.g. a packed output) never instantiates them.\n"
        "// B_in / B_out: a row's in- or out-fields by name (in_B(row), out_B(row)), for code that reads\n"
        "// a vector row's fields (a binding's drive, a test's cycle costs) without their positions.\n"
        "#pragma once\n\n#include <cstdint>\n#include <type_traits>\n#include <vector>\n\n"
        "namespace tu::cosim::glue {\n\nusing Row = std::vector<uint64_t>;\n";
  for (const Block& b : all()) {
    for (const auto& rename : b.ports) {  // a plain reference: clang 14 (the fuzz build) cannot capture a binding
      const std::string& field = rename.first;
      if (std::none_of(b.fields.begin(), b.fields.end(), [&](const vec::Field& f) { return f.name == field; }))
        throw std::logic_error("block " + b.name + ": port rename of unknown field '" + field + "' (to " +
                               rename.second + ")");
    }
    if (!is_identifier(b.name)) throw std::logic_error("block name '" + b.name + "' is not an identifier");
    std::ostringstream drive, sample, in_fields, out_fields, in_fill, out_fill;
    int k_in = 0, k_out = 0;
    for (const vec::Field& f : b.fields) {
      if (!is_identifier(f.name))
        throw std::logic_error("block " + b.name + ": field '" + f.name + "' is not an identifier");
      const auto renamed = b.ports.find(f.name);
      const std::string port = renamed == b.ports.end() ? f.name : renamed->second;
      if (f.role == vec::Role::In) {
        in_fields << "  uint64_t " << f.name << ";  // " << f.fmt.str() << "\n";
        in_fill << "  x." << f.name << " = r[" << k_in << "];\n";
        drive << "  d." << port << "_i = static_cast<std::decay_t<decltype(d." << port << "_i)>>(in[" << k_in++
              << "]);  // " << f.name << " " << f.fmt.str() << "\n";
      } else if (f.role == vec::Role::Out) {
        out_fields << "  uint64_t " << f.name << ";  // " << f.fmt.str() << "\n";
        out_fill << "  x." << f.name << " = r[" << k_out << "];\n";
        sample << (k_out++ ? ",\n" : "") << "             static_cast<uint64_t>(d." << port << "_o)";
      }
    }
    os << "\n// " << b.name << ": " << k_in << " in, " << k_out << " out\n"
       << "template <class V>\nvoid drive_" << b.name << "(V& d, const Row& in) {\n"
       << drive.str() << "}\n"
       << "template <class V>\nRow sample_" << b.name << "(V& d) {\n  return Row{\n"
       << sample.str() << "};\n}\n"
       << "struct " << b.name << "_in {\n" << in_fields.str() << "};\n"
       << "inline " << b.name << "_in in_" << b.name << "(const Row&" << (k_in ? " r" : "") << ") {\n  " << b.name
       << "_in x{};\n"
       << in_fill.str() << "  return x;\n}\n"
       << "struct " << b.name << "_out {\n" << out_fields.str() << "};\n"
       << "inline " << b.name << "_out out_" << b.name << "(const Row&" << (k_out ? " r" : "") << ") {\n  "
       << b.name << "_out x{};\n"
       << out_fill.str() << "  return x;\n}\n";
  }
  os << "\n}  // namespace tu::cosim::glue\n";
  return os.str();
}

}  // namespace tu::blocks
