// RTL bindings of the POM set-up, refinement and per-pixel unit (rtl/pom/tu_pom_{setup,refine,unit}.sv):
// ports named after the blocks' fields (generated glue); side_i (the corridor's back face, not a
// field of these blocks) is tied to the front face.
#include "Vtu_pom_refine.h"
#include "Vtu_pom_setup.h"
#include "Vtu_pom_unit.h"
#include "cosim.hpp"

namespace tu::cosim {

std::vector<RtlBlock> rtl_pom_unit() {
  auto setup_drive = [](Vtu_pom_setup& d, const Row& in) {
    glue::drive_pom_setup(d, in);
    d.side_i = 0;
  };
  auto refine_drive = [](Vtu_pom_refine& d, const Row& in) {
    glue::drive_pom_refine(d, in);
    d.side_i = 0;
  };
  return {make_rtl<Vtu_pom_setup>("pom_setup", setup_drive, glue::sample_pom_setup<Vtu_pom_setup>),
          make_rtl<Vtu_pom_refine>("pom_refine", refine_drive, glue::sample_pom_refine<Vtu_pom_refine>),
          make_rtl<Vtu_pom_unit>("pom_unit", glue::drive_pom_unit<Vtu_pom_unit>, glue::sample_pom_unit<Vtu_pom_unit>)};
}

}  // namespace tu::cosim
