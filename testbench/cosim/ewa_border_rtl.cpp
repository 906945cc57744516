// RTL binding of the EWA border weight (rtl/ewa/tu_ewa_border.sv, block ewa_border): ports named
// after the block's fields (generated glue).
#include "Vtu_ewa_border.h"
#include "cosim.hpp"

namespace tu::cosim {

RtlBlock rtl_ewa_border() {
  return make_rtl<Vtu_ewa_border>("ewa_border", glue::drive_ewa_border<Vtu_ewa_border>,
                                  glue::sample_ewa_border<Vtu_ewa_border>);
}

}  // namespace tu::cosim
