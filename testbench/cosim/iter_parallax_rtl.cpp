// RTL binding of the iterative parallax engine (rtl/pom/tu_iter_parallax.sv): ports named after
// the block's fields (generated glue); the iteration cap is a port, not a field.
#include "Vtu_iter_parallax.h"
#include "cosim.hpp"
#include "texunit/formats.hpp"

namespace tu::cosim {

RtlBlock rtl_iter_parallax() {
  auto drive = [](Vtu_iter_parallax& d, const Row& in) {
    glue::drive_iter_parallax(d, in);
    d.cap_i = fmt::kIpxCap;  // the block's vectors use the default cap
  };
  return make_rtl<Vtu_iter_parallax>("iter_parallax", drive, glue::sample_iter_parallax<Vtu_iter_parallax>);
}

}  // namespace tu::cosim
