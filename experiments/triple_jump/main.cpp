// triple_jump: the worked example of README "Adding a figure" -- 005 (Yoshida 1990), the fourth order of the
// triple-jump composition, on the quartic oscillator:
//   fourth order  largest energy error against h, fitted orders     order.cpp
#include "geomint/runner/experiment.hpp"

namespace geomint::triple_jump {
Study order_study();
}

int main(int argc, char** argv) {
  using namespace geomint;
  return run_experiment(argc, argv,
                        {.name = "triple_jump",
                         .description = "005 (Yoshida 1990): the fourth order of the triple-jump composition",
                         .studies = {triple_jump::order_study()}},
                        GEOMINT_EXPERIMENT_DIR);
}
