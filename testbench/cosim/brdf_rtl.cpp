// RTL bindings of the BRDF specular models (rtl/brdf/tu_brdf_<model>.sv): every top has the same
// ports (c_i, n_i, ccut_i -> f_o, flag_o).
#include "Vtu_brdf_blinn.h"
#include "Vtu_brdf_dsh.h"
#include "Vtu_brdf_msh.h"
#include "Vtu_brdf_msh_seq.h"
#include "Vtu_brdf_qr.h"
#include "Vtu_brdf_schlick.h"
#include "Vtu_brdf_scos2.h"
#include "Vtu_brdf_st16.h"
#include "cosim.hpp"

namespace tu::cosim {

namespace {
template <class V>
RtlBlock brdf_binding(const std::string& name) {
  auto drive = [](V& d, const Row& in) {
    d.c_i = static_cast<uint32_t>(in[0]);
    d.n_i = static_cast<uint16_t>(in[1]);
    d.ccut_i = static_cast<uint32_t>(in[2]);
  };
  auto sample = [](V& d) { return Row{d.f_o, d.flag_o}; };
  return make_rtl<V>(name, drive, sample);
}
}  // namespace

std::vector<RtlBlock> rtl_brdf() {
  return {brdf_binding<Vtu_brdf_blinn>("brdf_blinn"),     brdf_binding<Vtu_brdf_schlick>("brdf_schlick"),
          brdf_binding<Vtu_brdf_msh>("brdf_msh"),         brdf_binding<Vtu_brdf_msh_seq>("brdf_msh_seq"),
          brdf_binding<Vtu_brdf_dsh>("brdf_dsh"),         brdf_binding<Vtu_brdf_scos2>("brdf_scos2"),
          brdf_binding<Vtu_brdf_st16>("brdf_st16"),       brdf_binding<Vtu_brdf_qr>("brdf_qr")};
}

}  // namespace tu::cosim
