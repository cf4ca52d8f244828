#include "cli/cli.hpp"

int main(int argc, char** argv) {
  return gbssn1d::run_cli(argc, argv);
}
