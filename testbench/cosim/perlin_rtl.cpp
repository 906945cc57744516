// RTL bindings of the Perlin noise unit (rtl/noise/): blocks perlin3d and perlin2d on the
// pipelined scheme (tu_perlin3d, tu_perlin2d) and the octave-serial scheme on the same vectors
// (tu_perlin3d_serial, tu_perlin2d_serial; RTL names perlin3d_serial, perlin2d_serial). Ports
// named after the blocks' fields (generated glue).
#include "Vtu_perlin2d.h"
#include "Vtu_perlin2d_serial.h"
#include "Vtu_perlin3d.h"
#include "Vtu_perlin3d_serial.h"
#include "cosim.hpp"

namespace tu::cosim {

std::vector<RtlBlock> rtl_perlin() {
  std::vector<RtlBlock> r = {
      make_rtl<Vtu_perlin3d>("perlin3d", glue::drive_perlin3d<Vtu_perlin3d>, glue::sample_perlin3d<Vtu_perlin3d>),
      make_rtl<Vtu_perlin2d>("perlin2d", glue::drive_perlin2d<Vtu_perlin2d>, glue::sample_perlin2d<Vtu_perlin2d>),
      make_rtl<Vtu_perlin3d_serial>("perlin3d_serial", glue::drive_perlin3d<Vtu_perlin3d_serial>,
                                    glue::sample_perlin3d<Vtu_perlin3d_serial>),
      make_rtl<Vtu_perlin2d_serial>("perlin2d_serial", glue::drive_perlin2d<Vtu_perlin2d_serial>,
                                    glue::sample_perlin2d<Vtu_perlin2d_serial>)};
  r[2].block = "perlin3d", r[3].block = "perlin2d";  // the octave-serial scheme on the pipelined blocks' vectors
  return r;
}

}  // namespace tu::cosim
