// RTL binding of the POM march engine (rtl/pom/tu_pom_march.sv): ports named after the block's
// fields (generated glue); side_i (the corridor's back face) tied to the front face.
#include "Vtu_pom_march.h"
#include "cosim.hpp"

namespace tu::cosim {

RtlBlock rtl_pom_march() {
  auto drive = [](Vtu_pom_march& d, const Row& in) {
    glue::drive_pom_march(d, in);
    d.side_i = 0;
  };
  return make_rtl<Vtu_pom_march>("pom_march", drive, glue::sample_pom_march<Vtu_pom_march>);
}

}  // namespace tu::cosim
