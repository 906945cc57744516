// RTL bindings of the BRDF specular models (rtl/brdf/tu_brdf_<model>.sv): every top has the same
// ports (c_i, n_i, ccut_i -> f_o, flag_o), named after the brdf blocks' fields (generated glue).
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
// Every model's block has the blinn block's fields (c, n, ccut -> f, flag).
template <class V>
RtlBlock brdf_binding(const std::string& name) {
  return make_rtl<V>(name, glue::drive_brdf_blinn<V>, glue::sample_brdf_blinn<V>);
}
}  // namespace

std::vector<RtlBlock> rtl_brdf() {
  return {brdf_binding<Vtu_brdf_blinn>("brdf_blinn"),     brdf_binding<Vtu_brdf_schlick>("brdf_schlick"),
          brdf_binding<Vtu_brdf_msh>("brdf_msh"),         brdf_binding<Vtu_brdf_msh_seq>("brdf_msh_seq"),
          brdf_binding<Vtu_brdf_dsh>("brdf_dsh"),         brdf_binding<Vtu_brdf_scos2>("brdf_scos2"),
          brdf_binding<Vtu_brdf_st16>("brdf_st16"),       brdf_binding<Vtu_brdf_qr>("brdf_qr")};
}

}  // namespace tu::cosim
