// scripts/steering.py on the shipped river steerer (creatures/river_steerer.json,
// docs/rivercrossing.md): under random start headings it travels the
// resource's way whatever way it faced; with its landscape flat (its decision
// network silenced, the resource decided) it goes the same way relative to its
// body each time, an open loop. Real physics, six 2-minute evaluations each.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include "support/run_command.h"

namespace {

namespace fs = std::filesystem;
using bxtest::Outcome;

class Steering : public bxtest::InTempDir {
 protected:
  // steering.py over seeds 1-6 of `genome`: {toward the resource, along the start heading}
  std::pair<double, double> measure(const fs::path& genome, const std::string& sets, const std::string& tag) {
    std::string replays;
    for (int s = 1; s <= 6; ++s) {
      const fs::path r = dir / (tag + std::to_string(s) + ".json");
      Outcome o = bxtest::run_command(std::string(BESTIARY_BINARY) + " simulate " + genome.string() + " --seed " +
                                      std::to_string(s) + " --set task.start_yaw_jitter=180 " + sets + " --replay " +
                                      r.string());
      EXPECT_EQ(o.code, 0) << o.err;
      replays += " " + r.string();
    }
    Outcome o = bxtest::run_command("python3 " BESTIARY_SOURCE_DIR "/scripts/steering.py" + replays);
    EXPECT_EQ(o.code, 0) << o.err;
    double toward = -1, along = -1;
    EXPECT_EQ(std::sscanf(o.out.c_str(), "replays 6  toward the resource %lf  along the start heading %lf", &toward,
                          &along),
              2)
        << o.out;
    return {toward, along};
  }
};

TEST_F(Steering, TheShippedSteererGoesTheResourcesWayAndWithItsLandscapeFlatAnOpenLoopGoesItsBodysWay) {
  const fs::path steerer = BESTIARY_SOURCE_DIR "/creatures/river_steerer.json";
  auto [toward, along] = measure(steerer, "", "s");
  EXPECT_GT(toward, 0.8);  // measured 0.90
  EXPECT_LT(along, 0.5);   // 0.25
  // the same creature with genes 0-43 (its decision network) at 0 and the
  // resource left to it: every iota 0, a flat landscape
  const fs::path flat = dir / "flat.json";
  Outcome o = bxtest::run_command("python3 -c \"import json; j = json.load(open('" + steerer.string() +
                                  "')); j['genes'][:44] = [0.0] * 44; json.dump(j, open('" + flat.string() +
                                  "', 'w'))\"");
  ASSERT_EQ(o.code, 0) << o.err;
  auto [toward_flat, along_flat] = measure(flat, "--set river.resource_iota=decided", "f");
  EXPECT_GT(along_flat, 0.95);  // 1.00
  EXPECT_LT(toward_flat, 0.6);  // 0.36
  // a replay that is not the river's: one line, exit 2
  o = bxtest::run_command("python3 " BESTIARY_SOURCE_DIR "/scripts/steering.py " + (dir / "none.json").string());
  EXPECT_EQ(o.code, 2);
}

}  // namespace
