// RTL binding of the EWA border weight (rtl/ewa/tu_ewa_border.sv, block ewa_border).
#include "Vtu_ewa_border.h"
#include "cosim.hpp"

namespace tu::cosim {

RtlBlock rtl_ewa_border() {
  auto drive = [](Vtu_ewa_border& d, const Row& in) {
    d.q_i = in[0];
    d.xi_i = static_cast<uint32_t>(in[1]);
    d.eta_i = static_cast<uint32_t>(in[2]);
    d.kxu_i = static_cast<uint32_t>(in[3]);
    d.kxv_i = static_cast<uint32_t>(in[4]);
    d.kyu_i = static_cast<uint32_t>(in[5]);
    d.kyv_i = static_cast<uint32_t>(in[6]);
    d.w_i = static_cast<uint32_t>(in[7]);
  };
  auto sample = [](Vtu_ewa_border& d) { return Row{d.zone_o, d.d_o, d.w_o}; };
  RtlBlock b;
  b.name = "ewa_border";
  b.run = [=](const std::vector<Row>& in, const RunOptions& o) {
    return Harness<Vtu_ewa_border>(drive, sample).run(in, o);
  };
  b.timing = [=](const std::vector<Row>& in) { return Harness<Vtu_ewa_border>(drive, sample).measure_timing(in); };
  return b;
}

}  // namespace tu::cosim
