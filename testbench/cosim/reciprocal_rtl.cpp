// RTL binding of the reciprocal unit (rtl/reciprocal/tu_reciprocal.sv).
#include "Vtu_reciprocal.h"
#include "cosim.hpp"

namespace tu::cosim {

RtlBlock rtl_reciprocal() {
  auto drive = [](Vtu_reciprocal& d, const Row& in) { d.q_i = static_cast<uint32_t>(in[0]); };
  auto sample = [](Vtu_reciprocal& d) {
    return Row{d.mant_o, d.shift_o, d.flag_o};
  };
  RtlBlock b;
  b.name = "reciprocal";
  b.run = [=](const std::vector<Row>& in, const RunOptions& o) {
    return Harness<Vtu_reciprocal>(drive, sample).run(in, o);
  };
  b.timing = [=](const std::vector<Row>& in) {
    return Harness<Vtu_reciprocal>(drive, sample).measure_timing(in);
  };
  return b;
}

}  // namespace tu::cosim
