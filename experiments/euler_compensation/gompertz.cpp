// 000 Fig 3: explicit Euler on the Gompertz equation (17), in y and in ybar of (18).
#include <cmath>

#include "geomint/analysis/variable_compensation.hpp"
#include "geomint/methods/registry.hpp"
#include "geomint/runner/experiment.hpp"
#include "geomint/systems/gompertz.hpp"

namespace geomint::euler_compensation {
namespace {

void check_gompertz(const Scene& s) {
  if (s.real("gompertz.h") * s.real("gompertz.b") > method_info("explicit_euler").real_bound)
    s.reject("gompertz.h", "explicit Euler is unstable at the Gompertz equilibrium for h > 2/b = " +
                               format_double(2.0 / s.real("gompertz.b")));
  if (std::log(s.real("gompertz.y0")) >= s.real("gompertz.a") / s.real("gompertz.b"))
    s.reject("gompertz.y0", "the transformation (18) needs 0 < y0 < e^{a/b}");
  // (18) is defined below the equilibrium y* = e^{a/b} only; from y = y* e^{-u}, u > 0, Euler gives
  // y (1 + h b u), above y* where 1 + h b u > e^u: for small u whenever h b > 1, never for h b <= 1
  if (s.real("gompertz.h") * s.real("gompertz.b") > 1)
    s.reject("gompertz.h", "the transformation (18) needs y < e^{a/b}, and explicit Euler overshoots the equilibrium "
                           "e^{a/b} for h > 1/b = " + format_double(1.0 / s.real("gompertz.b")));
}

void run_gompertz(Context& ctx) {
  const Scene& s = ctx.scene;
  ctx.progress("Fig 3: explicit Euler in y and ybar");
  const Gompertz gompertz{s.real("gompertz.a"), s.real("gompertz.b")};
  const double y0 = s.real("gompertz.y0");
  write_compensated_euler_figure(ctx, "fig3_gompertz", "gompertz", gompertz,
                                 GompertzCompensation{gompertz.a, gompertz.b, y0}, y0, s.real("gompertz.h"),
                                 s.integer("gompertz.steps"));
}

StudyPlan plan_gompertz(const Scene& s) {
  return compensated_euler_plan(static_cast<double>(s.integer("gompertz.steps")), 1);
}

}  // namespace

Study gompertz_study() {
  return {.name = "gompertz",
          .makes = {{"000", "Fig. 3"}},
          .about = "explicit Euler on the Gompertz equation (17), in y and in ybar of (18)",
          .files = {"fig3_gompertz.csv", "fig3_gompertz_exact.csv"},
          .keys = Schema()
                      .real("gompertz.h", positive(),
                            "step of explicit Euler (Fig 3); h b <= 1 (the Euler iterates stay below the equilibrium, where "
                            "(18) is defined)")
                      .integer("gompertz.steps", at_least(1), "number of steps shown in Fig 3"),
          .reads = {"gompertz"},
          .run = run_gompertz,
          .validate = check_gompertz,
          .plan = plan_gompertz};
}

}  // namespace geomint::euler_compensation
