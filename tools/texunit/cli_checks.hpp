// Option checks shared by every subcommand. CLI11's own checks let some bad values through:
// CLI::Range compares, and NaN compares false, so `--stall-prob nan` passed; unsigned options
// are read with strtoull, which wraps "-3" to 2^64 - 3. Every usage error exits with code 2
// (main.cpp).
#pragma once

#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>

#include "texunit/shard.hpp"

namespace tu::cli {

constexpr int kUsageExit = 2;  // every usage error, as every bad input

// Every value given to a numeric option, by the type CLI11 records for it (check_values): a
// floating-point one finite (CLI::Range and NonNegativeNumber compare, and NaN compares false);
// an integer one in decimal and within 64 bits (CLI11 reads integers with strtoull / strtoll in
// base 0, so "010" was 8, "-3" wrapped and 2^64 saturated to 2^64 - 1).
inline CLI::Validator finite_number() {
  return CLI::Validator(
      [](std::string& s) -> std::string {
        char* end = nullptr;
        const double x = std::strtod(s.c_str(), &end);
        if (s.empty() || end != s.c_str() + s.size()) return "'" + s + "' is not a number";
        if (!std::isfinite(x)) return "'" + s + "' is not a finite number";
        return {};
      },
      "");
}
inline CLI::Validator decimal_integer(bool is_signed) {
  return CLI::Validator(
      [is_signed](std::string& s) -> std::string {
        const bool neg = is_signed && !s.empty() && s[0] == '-';
        const std::string d = s.substr(neg ? 1 : 0);
        const std::string what = is_signed ? "an integer" : "a non-negative integer";
        if (d.empty() || d.find_first_not_of("0123456789") != std::string::npos || (d.size() > 1 && d[0] == '0'))
          return "'" + s + "' is not " + what + " in decimal";
        // 2^64 - 1 has 20 digits; equal lengths compare as numbers.
        const std::string max = neg ? "9223372036854775808" : is_signed ? "9223372036854775807" : "18446744073709551615";
        if (d.size() > max.size() || (d.size() == max.size() && d > max))
          return "'" + s + "' is out of range (at most " + (neg ? "-" : "") + max + ")";
        return {};
      },
      "");
}
// An empty value (`--out ""`) names no file and no number: refused for every option.
inline CLI::Validator non_empty() {
  return CLI::Validator([](std::string& s) -> std::string { return s.empty() ? "empty value" : ""; }, "");
}

// Adds the checks above to every option of app and its subcommands (after the options are
// declared, before parsing): one mechanism for every numeric option, whichever command adds it.
inline void check_values(CLI::App& app) {
  for (CLI::Option* o : app.get_options()) {
    if (o->get_type_size_max() == 0) continue;  // a flag
    o->check(non_empty());
    const std::string t = o->get_type_name();
    const std::string base = t.substr(0, t.find(':'));
    if (base == "FLOAT") o->check(finite_number());
    else if (base == "INT") o->check(decimal_integer(true));
    else if (base == "UINT") o->check(decimal_integer(false));
  }
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) check_values(*sub);
}

// A finite number in [lo, hi].
inline CLI::Validator finite_in(double lo, double hi) {
  std::ostringstream desc;
  desc << "FINITE in [" << lo << " - " << hi << "]";
  return CLI::Validator(
      [lo, hi, d = desc.str()](std::string& s) -> std::string {
        char* end = nullptr;
        const double x = std::strtod(s.c_str(), &end);
        if (s.empty() || end != s.c_str() + s.size()) return "'" + s + "' is not a number";
        if (!std::isfinite(x) || x < lo || x > hi) return "'" + s + "' is not a " + d;
        return {};
      },
      desc.str());
}

// Decimal digits only (seeds, counts): no sign, no hex or octal prefix.
inline CLI::Validator non_negative_integer() {
  return CLI::Validator(
      [](std::string& s) -> std::string {
        if (s.empty() || s.find_first_not_of("0123456789") != std::string::npos)
          return "'" + s + "' is not a non-negative decimal integer";
        return {};
      },
      "UINT");
}

// `--shard K/N` (texunit/shard.hpp): 0 <= K < N.
inline CLI::Validator shard_spec() {
  return CLI::Validator(
      [](std::string& s) -> std::string {
        try {
          tu::Shard::parse(s);
        } catch (const std::invalid_argument& e) {
          return e.what();
        }
        return {};
      },
      "K/N");
}

// An odd integer in [lo, hi] (filter sizes).
inline CLI::Validator odd_in(int lo, int hi) {
  return CLI::Validator(
      [lo, hi](std::string& s) -> std::string {
        char* end = nullptr;
        const long x = std::strtol(s.c_str(), &end, 10);
        if (s.empty() || end != s.c_str() + s.size()) return "'" + s + "' is not an integer";
        if (x < lo || x > hi || x % 2 == 0)
          return "'" + s + "' is not an odd integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
        return {};
      },
      "ODD");
}

// A positive integer dividing n (`what` names n in the message).
inline CLI::Validator divisor_of(int n, const std::string& what) {
  return CLI::Validator(
      [n, what](std::string& s) -> std::string {
        char* end = nullptr;
        const long x = std::strtol(s.c_str(), &end, 10);
        if (s.empty() || end != s.c_str() + s.size()) return "'" + s + "' is not an integer";
        if (x < 1 || x > n || n % x != 0) return "'" + s + "' does not divide " + what + " (" + std::to_string(n) + ")";
        return {};
      },
      "DIVISOR");
}

}  // namespace tu::cli
