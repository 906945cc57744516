#include <bit>
#include <cmath>

#include "brdf_blinn.hpp"
#include "brdf_common.hpp"
#include "brdf_dsh.hpp"
#include "brdf_msh.hpp"
#include "brdf_qr.hpp"
#include "brdf_ref.hpp"
#include "brdf_schlick.hpp"
#include "brdf_scos2.hpp"
#include "brdf_st16.hpp"

namespace tu::brdf {

std::string name(Model m) {
  switch (m) {
    case Model::Blinn: return "blinn";
    case Model::Schlick: return "schlick";
    case Model::Msh: return "msh";
    case Model::Dsh: return "dsh";
    case Model::Scos2: return "scos2";
    case Model::St16: return "st16";
    case Model::Qr: return "qr";
  }
  return "?";
}

Front front(const In& in) {
  Front f;
  const i128 one = i128(1) << fmt::kBrdfCF;
  i128 c = CIn::from_bits(in.c).raw();
  if (c > one) {
    c = one;
    f.flag = true;
  }
  if (c < 0) c = 0;  // back-facing: F(0)
  int n = static_cast<int>(in.n & ((1u << fmt::kBrdfNW) - 1));
  if (n < 1 || n > fmt::kBrdfNMax) {
    n = n < 1 ? 1 : fmt::kBrdfNMax;
    f.flag = true;
  }
  f.n = n;
  f.c = C::from_raw(c);
  f.t = C::from_raw(one - c);
  f.u = (UFixed<fmt::kBrdfNW, 0>::from_raw(n) * f.t).as<U>();  // exact
  f.cut = static_cast<uint64_t>(c) < in.ccut;
  return f;
}

Recip recip_of(u128 v) {
  const int p = v >> 64 ? 127 - std::countl_zero(static_cast<uint64_t>(v >> 64))
                        : 63 - std::countl_zero(static_cast<uint64_t>(v));
  constexpr int kTop = fmt::kRecipMantW - 1;
  const u128 m = p <= kTop ? v << (kTop - p) : v >> (p - kTop);  // truncated mantissa
  return {recip::core(recip::Mant::from_raw(static_cast<i128>(m))), p};
}

double ref_value(Model m, double c, int n) {
  switch (m) {
    case Model::Blinn: return ref::blinn(c, n);
    case Model::Schlick: return ref::schlick(c, n);
    case Model::Msh: return ref::msh(c, n);
    case Model::Dsh: return ref::dsh(c, n);
    case Model::Scos2: return ref::scos2(c, n);
    case Model::St16: return ref::st(c, n, 16);
    case Model::Qr: return ref::qr(c, n);
  }
  return 0;
}

uint64_t cut_code(Model m, int n, int q) {
  const double level = std::ldexp(1.0, -q);
  uint64_t lo = 0, hi = uint64_t(1) << fmt::kBrdfCF;  // answer in [lo, hi + 1]
  if (ref_value(m, 0.0, n) >= level) return 0;
  if (ref_value(m, 1.0, n) < level) return hi + 1;
  while (hi - lo > 1) {  // invariant: F(lo) < level <= F(hi)
    const uint64_t mid = (lo + hi) / 2;
    if (ref_value(m, std::ldexp(static_cast<double>(mid), -fmt::kBrdfCF), n) >= level) hi = mid;
    else lo = mid;
  }
  return hi;
}

Result eval(Model m, const In& in) {
  switch (m) {
    case Model::Blinn: return blinn(in);
    case Model::Schlick: return schlick(in);
    case Model::Msh: return msh(in);
    case Model::Dsh: return dsh(in);
    case Model::Scos2: return scos2(in);
    case Model::St16: return st16(in);
    case Model::Qr: return qr(in);
  }
  return {};
}

}  // namespace tu::brdf
