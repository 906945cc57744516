// RTL binding of the reciprocal unit (rtl/reciprocal/tu_reciprocal.sv).
#include "Vtu_reciprocal.h"
#include "cosim.hpp"

namespace tu::cosim {

RtlBlock rtl_reciprocal() {
  return make_rtl<Vtu_reciprocal>("reciprocal", glue::drive_reciprocal<Vtu_reciprocal>,
                                  glue::sample_reciprocal<Vtu_reciprocal>);
}

}  // namespace tu::cosim
