// tu_gen_glue OUT: writes the co-simulation's drive/sample glue (tu::blocks::generated_glue) to OUT,
// leaving the file untouched when it is unchanged (so that dependants are not rebuilt).
#include <fstream>
#include <iostream>
#include <sstream>

#include "glue_gen.hpp"
#include "texunit/output.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: tu_gen_glue OUT.hpp\n";
    return 2;
  }
  const std::string content = tu::blocks::generated_glue();
  std::ostringstream old;
  if (std::ifstream in(argv[1], std::ios::binary); in) old << in.rdbuf();
  if (old.str() == content) return 0;
  try {
    tu::out::write_atomic(argv[1], content);  // checked, all or none
  } catch (const std::exception& e) {
    std::cerr << e.what() << "\n";
    return 1;
  }
  return 0;
}
