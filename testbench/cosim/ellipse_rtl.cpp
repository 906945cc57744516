// RTL bindings of the pixel-footprint units rtl/ellipse/tu_ellipse.sv (block "ellipse", analytic)
// and rtl/ellipse/tu_ellipse_rec.sv (block "ellipse_rec", the seed's recurrences): ports named
// after the blocks' fields (generated glue).
#include "Vtu_ellipse.h"
#include "Vtu_ellipse_rec.h"
#include "cosim.hpp"

namespace tu::cosim {

RtlBlock rtl_ellipse() {
  return make_rtl<Vtu_ellipse>("ellipse", glue::drive_ellipse<Vtu_ellipse>, glue::sample_ellipse<Vtu_ellipse>);
}

RtlBlock rtl_ellipse_rec() {
  return make_rtl<Vtu_ellipse_rec>("ellipse_rec", glue::drive_ellipse_rec<Vtu_ellipse_rec>,
                                   glue::sample_ellipse_rec<Vtu_ellipse_rec>);
}

}  // namespace tu::cosim
