// `bestiary crosscheck`: a creature's evaluation in ODE, then its recorded
// effector signals replayed open loop in MuJoCo (io/mujoco_replay.h): does
// it move the same way in a second simulator?
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>

#include "cli/commands.h"
#include "cli/creature.h"
#include "genome/json_text.h"
#include "io/mujoco_replay.h"

namespace bx {

namespace {

struct CrosscheckArgs {
  std::string target;  ///< a genome file or a run's creature (cli/creature.h)
  CreatureFlags flags;
  bool json = false;
};

// Within these the two simulators agree (docs/export.md, "A second simulator").
constexpr double kMaxHeadingDegrees = 45, kMinRatio = 0.5, kMaxRatio = 2;

double degrees(double rad) { return rad * 180 / kPi; }

double heading_deg(Vec3 v) { return degrees(std::atan2(v.y, v.x)); }

double planar(Vec3 v) { return std::hypot(v.x, v.y); }

// MuJoCo's score over ODE's (null when ODE's is 0)
nlohmann::json fitness_ratio(double mujoco, double ode) { return ode != 0 ? nlohmann::json(mujoco / ode) : nlohmann::json(); }

int cmd_crosscheck(const CrosscheckArgs& a) {
  auto subject = resolve_creature(a.target, a.flags);
  if (!subject) return fail(subject.error());
  const SimConfig& sim = subject->cfg.sim;
  if (!has_body(sim.creature)) return fail(no_body(sim.creature, "nothing to replay in MuJoCo"));
  auto creature = subject->develop();
  if (!creature) return fail(subject->label + ": not viable: " + creature.error());
  auto r = crosscheck_mujoco(*creature->body, *creature->controller, sim, subject->seed);
  if (!r) return fail(subject->label + ": cannot replay it in MuJoCo: " + r.error());
  const double head = degrees(r->heading_difference);
  // a creature that moves less than a tenth of its length in ODE gives no heading to compare
  const bool moved = planar(r->ode) >= 0.1 * creature->body->body_length();
  const bool agrees = moved && head <= kMaxHeadingDegrees && r->distance_ratio >= kMinRatio &&
                      r->distance_ratio <= kMaxRatio;
  if (a.json) {
    nlohmann::json out;
    out["creature"] = subject->label;
    out["seed"] = subject->seed;
    out["from"] = r->from;
    out["to"] = r->to;
    out["seconds"] = r->seconds;
    out["steps"] = r->steps;
    out["tracked"] = r->tracked;
    out["ode_fitness"] = r->ode_fitness;
    out["ode_muscle_work"] = r->ode_muscle_work;
    out["mujoco_fitness"] = r->mujoco_fitness;
    out["fitness_ratio"] = fitness_ratio(r->mujoco_fitness, r->ode_fitness);
    out["ode"] = {r->ode.x, r->ode.y, r->ode.z};
    nlohmann::json variants = nlohmann::json::array();
    for (const CrossSimVariant& v : r->variants)
      variants.push_back({{"contacts", v.name},
                          {"mujoco", {v.displacement.x, v.displacement.y, v.displacement.z}},
                          {"heading_difference_deg", degrees(v.heading_difference)},
                          {"distance_ratio", v.distance_ratio},
                          {"min_height", v.min_height},
                          {"first_second_angle_gap", v.first_second_angle_gap},
                          {"fitness", v.fitness},
                          {"muscle_work", v.muscle_work},
                          {"fitness_ratio", fitness_ratio(v.fitness, r->ode_fitness)},
                          {"from", v.from},
                          {"to", v.to},
                          {"flight", r->has_flight ? nlohmann::json{v.flight.x, v.flight.y, v.flight.z} : nlohmann::json()},
                          {"flight_heading_difference_deg", degrees(v.flight_heading_difference)},
                          {"flight_ratio", v.flight_ratio},
                          {"warnings", v.warnings}});
    out["variants"] = variants;
    if (r->has_flight) {
      out["ode_flight"] = {r->ode_flight.x, r->ode_flight.y, r->ode_flight.z};
      out["landing"] = r->landing;
      out["flight_heading_difference_deg"] = degrees(r->flight_heading_difference);
      out["flight_ratio"] = r->flight_ratio;
    }
    out["heading_difference_deg"] = head;
    out["distance_ratio"] = r->distance_ratio;
    out["moved"] = moved;
    out["agrees"] = agrees;
    std::printf("%s\n", json_text(out).c_str());
    return 0;
  }
  std::printf("%s, seed %llu\n", subject->label.c_str(), static_cast<unsigned long long>(subject->seed));
  std::printf("ODE, closed loop: %.2f s (%ld steps of %.6g s); task score %.6g; over the task's scored span "
              "(%.2f-%.2f s) its %s moved %.3f m at heading %.1f deg\n",
              r->seconds, r->steps, sim.physics.dt, r->ode_fitness, r->from, r->to, r->tracked.c_str(),
              planar(r->ode), heading_deg(r->ode));
  if (!creature->body->muscles.empty()) std::printf("  its muscles' work: %.4g J\n", r->ode_muscle_work);
  if (r->has_flight)
    std::printf("  its flight, until it first touches the ground (%.2f s): %.3f m at heading %.1f deg\n", r->landing,
                planar(r->ode_flight), heading_deg(r->ode_flight));
  std::printf("MuJoCo, ODE's motor commands open loop, the same task scoring it, by its contacts:\n");
  for (const CrossSimVariant& v : r->variants) {
    std::printf("  %s: task score %.6g, scored %.2f-%.2f s", v.name.c_str(), v.fitness, v.from, v.to);
    if (!creature->body->muscles.empty()) std::printf("; its muscles' work %.4g J", v.muscle_work);
    std::printf("\n");
    std::printf("    %6.3f m at heading %6.1f deg: %5.1f deg off, ratio %.2f; joints %.3f rad apart in 1 s\n",
                planar(v.displacement), heading_deg(v.displacement), degrees(v.heading_difference), v.distance_ratio,
                v.first_second_angle_gap);
    if (r->has_flight)
      std::printf("    flight %.3f m at heading %.1f deg: %.1f deg off, ratio %.2f\n", planar(v.flight),
                  heading_deg(v.flight), degrees(v.flight_heading_difference), v.flight_ratio);
    for (const std::string& w : v.warnings) std::printf("    MuJoCo warned: %s\n", w.c_str());
  }
  std::printf("task score: %.6g in ODE, median %.6g in MuJoCo\n", r->ode_fitness, r->mujoco_fitness);
  if (r->has_flight)
    std::printf("flight: median %.1f deg off, ratio %.2f\n", degrees(r->flight_heading_difference), r->flight_ratio);
  if (!moved) {
    std::printf("it moves less than a tenth of its length (%.3f m) in ODE over that span: nothing to compare\n",
                creature->body->body_length());
    return 0;
  }
  std::printf("median: %.1f deg off, ratio %.2f (MuJoCo / ODE): %s (within %.0f deg and %.1f-%.0fx)\n", head,
              r->distance_ratio, agrees ? "the same way" : "NOT the same way", kMaxHeadingDegrees, kMinRatio,
              kMaxRatio);
  return 0;
}

}  // namespace

void add_crosscheck_command(CLI::App& app) {
  static CrosscheckArgs a;
  auto* c = app.add_subcommand(
      "crosscheck", "Replay a creature's effector signals open loop in MuJoCo: does it move the same way as in ODE?");
  add_creature_options(c, a.target, a.flags);
  c->add_flag("--json", a.json, "Print one JSON object");
  c->footer("Exit code 0: compared (the verdict is printed); 2: bad input, or a creature MuJoCo cannot replay.");
  c->callback([] { std::exit(cmd_crosscheck(a)); });
}

}  // namespace bx
