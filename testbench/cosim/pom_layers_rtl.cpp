// RTL binding of the adaptive POM layer counter (rtl/pom/tu_pom_layers.sv).
#include "Vtu_pom_layers.h"
#include "cosim.hpp"

namespace tu::cosim {

RtlBlock rtl_pom_layers() {
  auto drive = [](Vtu_pom_layers& d, const Row& in) {
    d.vz_i = static_cast<uint16_t>(in[0]);
    d.c_i = static_cast<uint8_t>(in[1]);
    d.nmin_i = static_cast<uint8_t>(in[2]);
    d.nmax_i = static_cast<uint8_t>(in[3]);
  };
  auto sample = [](Vtu_pom_layers& d) { return Row{d.n_o, d.neg_o}; };
  RtlBlock b;
  b.name = "pom_layers";
  b.run = [=](const std::vector<Row>& in, const RunOptions& o) {
    return Harness<Vtu_pom_layers>(drive, sample).run(in, o);
  };
  b.timing = [=](const std::vector<Row>& in) {
    return Harness<Vtu_pom_layers>(drive, sample).measure_timing(in);
  };
  return b;
}

}  // namespace tu::cosim
