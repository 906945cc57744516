// RTL binding of the iterative parallax engine (rtl/pom/tu_iter_parallax.sv).
#include "Vtu_iter_parallax.h"
#include "cosim.hpp"

namespace tu::cosim {

RtlBlock rtl_iter_parallax() {
  auto drive = [](Vtu_iter_parallax& d, const Row& in) {
    d.u_i = static_cast<uint32_t>(in[0]);
    d.v_i = static_cast<uint32_t>(in[1]);
    d.su_i = static_cast<uint32_t>(in[2]);
    d.sv_i = static_cast<uint32_t>(in[3]);
    d.sh_i = static_cast<uint32_t>(in[4]);
  };
  auto sample = [](Vtu_iter_parallax& d) {
    return Row{d.u_o, d.v_o, d.iters_o, d.nonconv_o};
  };
  RtlBlock b;
  b.name = "iter_parallax";
  b.run = [=](const std::vector<Row>& in, const RunOptions& o) {
    return Harness<Vtu_iter_parallax>(drive, sample).run(in, o);
  };
  b.timing = [=](const std::vector<Row>& in) {
    return Harness<Vtu_iter_parallax>(drive, sample).measure_timing(in);
  };
  return b;
}

}  // namespace tu::cosim
