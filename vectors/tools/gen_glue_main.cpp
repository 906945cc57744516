// tu_gen_glue OUT: writes the co-simulation's drive/sample glue (tu::blocks::generated_glue) to OUT,
// leaving the file untouched when it is unchanged (so that dependants are not rebuilt).
#include <fstream>
#include <iostream>
#include <sstream>

#include "glue_gen.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: tu_gen_glue OUT.hpp\n";
    return 2;
  }
  const std::string content = tu::blocks::generated_glue();
  std::ostringstream old;
  if (std::ifstream in(argv[1], std::ios::binary); in) old << in.rdbuf();
  if (old.str() == content) return 0;
  std::ofstream out(argv[1], std::ios::binary);
  if (!(out << content)) {
    std::cerr << argv[1] << ": cannot write the file\n";
    return 1;
  }
  return 0;
}
