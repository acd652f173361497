#include <iostream>
#include "formats/matrix_json.hpp"
#include "testgen/testgen.hpp"
int main(int argc, char** argv) {
  auto m = cemv::formats::load_valid_matrix(argv[1], "x");
  auto objs = cemv::testgen::derive_objectives(m);
  std::string text = cemv::testgen::objectives_file_text(m, objs);
  if (argc > 2) std::cout << text;
  std::cout << objs.size() << " objectives\n";
}
