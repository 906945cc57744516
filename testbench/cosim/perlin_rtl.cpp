// RTL bindings of the Perlin noise unit (rtl/noise/): blocks perlin3d and perlin2d on the
// pipelined scheme (tu_perlin3d, tu_perlin2d) and the octave-serial scheme on the same vectors
// (tu_perlin3d_serial, tu_perlin2d_serial; RTL names perlin3d_serial, perlin2d_serial).
#include "Vtu_perlin2d.h"
#include "Vtu_perlin2d_serial.h"
#include "Vtu_perlin3d.h"
#include "Vtu_perlin3d_serial.h"
#include "cosim.hpp"

namespace tu::cosim {

namespace {
template <class V>
RtlBlock perlin3(const std::string& name) {
  auto drive = [](V& d, const Row& in) {
    d.x_i = static_cast<uint32_t>(in[0]);
    d.y_i = static_cast<uint32_t>(in[1]);
    d.z_i = static_cast<uint32_t>(in[2]);
  };
  return make_rtl<V>(name, drive, [](V& d) { return Row{d.fbm_o}; });
}
template <class V>
RtlBlock perlin2(const std::string& name) {
  auto drive = [](V& d, const Row& in) {
    d.x_i = static_cast<uint32_t>(in[0]);
    d.y_i = static_cast<uint32_t>(in[1]);
  };
  return make_rtl<V>(name, drive, [](V& d) { return Row{d.fbm_o}; });
}
}  // namespace

std::vector<RtlBlock> rtl_perlin() {
  return {perlin3<Vtu_perlin3d>("perlin3d"), perlin2<Vtu_perlin2d>("perlin2d"),
          perlin3<Vtu_perlin3d_serial>("perlin3d_serial"), perlin2<Vtu_perlin2d_serial>("perlin2d_serial")};
}

}  // namespace tu::cosim
