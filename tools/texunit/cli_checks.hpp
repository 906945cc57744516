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
