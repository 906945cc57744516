#include "vector_file.hpp"

#include "texunit/shard.hpp"

#include <bit>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "texunit/output.hpp"
#include "texunit/text.hpp"

namespace tu::vec {

FormatError::FormatError(const std::string& what) : std::runtime_error(printable(what)) {}

namespace {
const char* role_name(Role r) { return r == Role::In ? "in" : r == Role::Out ? "out" : "ref"; }

[[noreturn]] void fail(const std::string& file, int line, const std::string& why) {
  throw FormatError(file + ":" + std::to_string(line) + ": " + why);
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

std::vector<std::string> split_ws(const std::string& s) {
  std::istringstream is(s);
  std::vector<std::string> out;
  for (std::string t; is >> t;) out.push_back(t);
  return out;
}
}  // namespace

std::string FieldFormat::str() const {
  if (is_f64) return "f64";
  return std::string(is_signed ? "s" : "u") + std::to_string(w) + "." + std::to_string(f);
}

FieldFormat FieldFormat::parse(const std::string& s) {
  FieldFormat ff;
  if (s == "f64") {
    ff.is_f64 = true;
    ff.w = 64;
    return ff;
  }
  if (s.size() < 4 || (s[0] != 's' && s[0] != 'u'))
    throw std::invalid_argument("format '" + s + "' is not sW.F, uW.F or f64");
  ff.is_signed = s[0] == 's';
  const auto dot = s.find('.');
  if (dot == std::string::npos) throw std::invalid_argument("format '" + s + "' has no '.'");
  try {
    size_t used = 0;
    ff.w = std::stoi(s.substr(1, dot - 1), &used);
    if (used != dot - 1) throw std::invalid_argument("");
    const std::string fs = s.substr(dot + 1);
    ff.f = std::stoi(fs, &used);
    if (used != fs.size()) throw std::invalid_argument("");
  } catch (const std::exception&) {
    throw std::invalid_argument("format '" + s + "' has a malformed width or fraction");
  }
  if (ff.w < 1 || ff.w > 64) throw std::invalid_argument("format '" + s + "': width must be 1..64");
  return ff;
}

std::vector<int> VectorFile::indices(Role r) const {
  std::vector<int> out;
  for (size_t i = 0; i < fields.size(); ++i)
    if (fields[i].role == r) out.push_back(static_cast<int>(i));
  return out;
}

int VectorFile::index_of(const std::string& name) const {
  for (size_t i = 0; i < fields.size(); ++i)
    if (fields[i].name == name) return static_cast<int>(i);
  return -1;
}

VectorFile parse(const std::string& text, const std::string& name) {
  VectorFile v;
  std::istringstream is(text);
  std::string line;
  int ln = 0;
  bool magic = false, have_block = false, have_fields = false, have_set = false, have_seed = false;
  while (std::getline(is, line)) {
    ++ln;
    const std::string t = trim(line);
    if (t.empty()) continue;
    if (t[0] == '#') {
      const std::string body = trim(t.substr(1));
      if (ln == 1 || !magic) {
        if (body != "texunit-vectors 1")
          fail(name, ln, "expected header '# texunit-vectors 1' as the first line");
        magic = true;
        continue;
      }
      const auto colon = body.find(':');
      if (colon == std::string::npos) continue;  // free comment
      const std::string key = trim(body.substr(0, colon));
      const std::string val = trim(body.substr(colon + 1));
      if (!v.rows.empty() && (key == "block" || key == "fields"))
        fail(name, ln, "header key '" + key + "' after the first data line");
      if (key == "block") {
        if (val.empty()) fail(name, ln, "empty block name");
        v.block = val;
        have_block = true;
      } else if (key == "set") {
        v.set = val;
        have_set = true;
      } else if (key == "seed") {
        try {
          size_t used = 0;
          // Digits only: std::stoull would wrap a leading '-' to 2^64 - n.
          if (val.empty() || val.find_first_not_of("0123456789") != std::string::npos)
            throw std::invalid_argument("");
          v.seed = std::stoull(val, &used);
          if (used != val.size()) throw std::invalid_argument("");
        } catch (const std::exception&) {
          fail(name, ln, "seed '" + val + "' is not an unsigned integer");
        }
        have_seed = true;
      } else if (key == "shard") {
        // "K/N first F": Shard::parse checks K/N; F is decimal digits.
        const auto sp = val.find(" first ");
        const std::string f = sp == std::string::npos ? "" : trim(val.substr(sp + 7));
        try {
          if (f.empty() || f.size() > 19 || f.find_first_not_of("0123456789") != std::string::npos)
            throw std::invalid_argument("");
          v.shard = Shard::parse(val.substr(0, sp)).str();
          v.first_vector = std::stoull(f);
        } catch (const std::exception&) {
          fail(name, ln, "shard '" + val + "' is not 'K/N first F' (0 <= K < N, F a decimal row index)");
        }
      } else if (key == "fields") {
        for (const auto& tok : split_ws(val)) {
          const auto c1 = tok.find(':');
          const auto c2 = tok.find(':', c1 == std::string::npos ? 0 : c1 + 1);
          if (c1 == std::string::npos || c2 == std::string::npos)
            fail(name, ln, "field '" + tok + "' is not name:role:format");
          Field f;
          f.name = tok.substr(0, c1);
          const std::string role = tok.substr(c1 + 1, c2 - c1 - 1);
          if (role == "in") f.role = Role::In;
          else if (role == "out") f.role = Role::Out;
          else if (role == "ref") f.role = Role::Ref;
          else fail(name, ln, "field '" + f.name + "': role '" + role + "' is not in/out/ref");
          try {
            f.fmt = FieldFormat::parse(tok.substr(c2 + 1));
          } catch (const std::invalid_argument& e) {
            fail(name, ln, "field '" + f.name + "': " + e.what());
          }
          if (f.name.empty()) fail(name, ln, "field with an empty name");
          for (const auto& g : v.fields)
            if (g.name == f.name) fail(name, ln, "field '" + f.name + "' declared twice");
          v.fields.push_back(f);
        }
        if (v.fields.empty()) fail(name, ln, "'fields:' declares no field");
        have_fields = true;
      }
      continue;
    }
    if (!magic) fail(name, ln, "expected header '# texunit-vectors 1' as the first line");
    if (!have_block || !have_fields || !have_set || !have_seed)
      fail(name, ln, "data line before the header declared block, set, seed and fields");
    const auto toks = split_ws(t);
    if (toks.size() != v.fields.size())
      fail(name, ln, "expected " + std::to_string(v.fields.size()) + " fields, found " +
                         std::to_string(toks.size()));
    std::vector<uint64_t> row(toks.size());
    for (size_t i = 0; i < toks.size(); ++i) {
      const Field& f = v.fields[i];
      const std::string& h = toks[i];
      const size_t max_digits = static_cast<size_t>((f.fmt.w + 3) / 4);
      if (h.size() > max_digits)
        fail(name, ln, "field '" + f.name + "': '" + h + "' has more than " +
                           std::to_string(max_digits) + " hex digits");
      uint64_t x = 0;
      for (char c : h) {
        int d;
        if (c >= '0' && c <= '9') d = c - '0';
        else if (c >= 'a' && c <= 'f') d = c - 'a' + 10;
        else if (c >= 'A' && c <= 'F') d = c - 'A' + 10;
        else fail(name, ln, "field '" + f.name + "': '" + h + "' is not hexadecimal");
        x = (x << 4) | static_cast<uint64_t>(d);
      }
      if (f.fmt.w < 64 && (x >> f.fmt.w) != 0)
        fail(name, ln, "field '" + f.name + "': " + h + " does not fit in " +
                           std::to_string(f.fmt.w) + " bits");
      row[i] = x;
    }
    v.rows.push_back(std::move(row));
  }
  if (!magic) fail(name, ln == 0 ? 1 : ln, "empty file or missing header '# texunit-vectors 1'");
  if (!have_block || !have_fields || !have_set || !have_seed)
    fail(name, ln, "header incomplete: block, set, seed and fields are all required");
  return v;
}

VectorFile read(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FormatError(path + ":0: cannot open file");
  std::ostringstream ss;
  ss << in.rdbuf();
  return parse(ss.str(), path);
}

std::string serialise(const VectorFile& v) {
  std::ostringstream os;
  serialise(v, os);
  return os.str();
}

void serialise(const VectorFile& v, std::ostream& os) {
  os << "# texunit-vectors 1\n# block: " << v.block << "\n# set: " << v.set
     << "\n# seed: " << v.seed;
  if (!v.shard.empty()) os << "\n# shard: " << v.shard << " first " << v.first_vector;
  os << "\n# fields:";
  for (const auto& f : v.fields) os << ' ' << f.name << ':' << role_name(f.role) << ':' << f.fmt.str();
  os << '\n';
  char buf[24];
  for (const auto& r : v.rows) {
    for (size_t i = 0; i < r.size(); ++i) {
      const int digits = (v.fields[i].fmt.w + 3) / 4;
      std::snprintf(buf, sizeof buf, "%0*llx", digits, static_cast<unsigned long long>(r[i]));
      if (i) os << ' ';
      os << buf;
    }
    os << '\n';
  }
}

void write(const VectorFile& v, const std::string& path) {
  // Streamed through the checked output path: no second copy of a large file in memory, every
  // write checked, renamed into place only when whole.
  try {
    out::write_atomic(path, [&](std::ostream& os) { serialise(v, os); });
  } catch (const std::runtime_error& e) {
    throw FormatError(e.what());
  }
}

uint64_t f64_bits(double x) { return std::bit_cast<uint64_t>(x); }
double bits_f64(uint64_t b) { return std::bit_cast<double>(b); }
int64_t sext(uint64_t raw, int w) {
  if (w >= 64) return static_cast<int64_t>(raw);
  const uint64_t m = uint64_t(1) << (w - 1);
  raw &= (uint64_t(1) << w) - 1;
  return static_cast<int64_t>((raw ^ m) - m);
}

}  // namespace tu::vec
