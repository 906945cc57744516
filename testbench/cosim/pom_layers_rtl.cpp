// RTL binding of the adaptive POM layer counter (rtl/pom/tu_pom_layers.sv): ports named after the
// block's fields (generated glue).
#include "Vtu_pom_layers.h"
#include "cosim.hpp"

namespace tu::cosim {

RtlBlock rtl_pom_layers() {
  return make_rtl<Vtu_pom_layers>("pom_layers", glue::drive_pom_layers<Vtu_pom_layers>,
                                  glue::sample_pom_layers<Vtu_pom_layers>);
}

}  // namespace tu::cosim
