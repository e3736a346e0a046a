// `bestiary export CREATURE --mjcf OUT.xml` (and `--urdf OUT.urdf`) from the
// command line: a genome file and a run's creature are written and say what
// they hold; what cannot be exported is refused in one line and writes nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "support/run_command.h"

namespace {

namespace fs = std::filesystem;
using bxtest::bestiary;
using bxtest::Outcome;

class ExportMjcf : public bxtest::InTempDir {};

TEST_F(ExportMjcf, AGenomeFileAndARunsCreatureAreWritten) {
  Outcome r = bestiary("export " + bxtest::creature("centipede.json") + " --mjcf " + (dir / "c.xml").string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("12 bodies, 11 joints, 11 effectors"), std::string::npos) << r.out;
  const std::string xml = bxtest::slurp(dir / "c.xml");
  EXPECT_NE(xml.find("<freejoint name=\"root\"/>"), std::string::npos);
  EXPECT_EQ(std::count(xml.begin(), xml.end(), '\n') > 20, true);
  // muscles as spatial tendons, whose stiffness the note says how to set
  r = bestiary("export " + bxtest::creature("lessin_crawler.json") + " --mjcf " + (dir / "l.xml").string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("note: 24 muscles as spatial tendons"), std::string::npos) << r.out;
  const std::string lx = bxtest::slurp(dir / "l.xml");
  EXPECT_NE(lx.find("<spatial name=\"m23\""), std::string::npos);
  EXPECT_NE(lx.find("<site name=\"m23b\""), std::string::npos);
  // a run's best
  const fs::path run = dir / "r";
  ASSERT_EQ(bxtest::small_run(run).code, 0);
  r = bestiary("export " + run.string() + " --mjcf " + (dir / "best.xml").string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir / "best.xml"));
}

TEST_F(ExportMjcf, AsUrdfTooWithWhatUrdfCannotSay) {
  Outcome r = bestiary("export " + bxtest::creature("centipede.json") + " --urdf " + (dir / "c.urdf").string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("12 links, 11 joints"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("note: URDF has no actuators"), std::string::npos) << r.out;
  const std::string urdf = bxtest::slurp(dir / "c.urdf");
  EXPECT_NE(urdf.find("<robot name="), std::string::npos);
  EXPECT_EQ(std::count(urdf.begin(), urdf.end(), '\n') > 20, true);
  r = bestiary("export " + bxtest::creature("lessin_crawler.json") + " --urdf " + (dir / "l.urdf").string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("note: 24 muscle effectors not exported"), std::string::npos) << r.out;
  for (const std::string& bad : {bxtest::creature("centipede.json") + " --urdf " + (dir / "x.xml").string(),
                                 bxtest::creature("centipede.json") + " --urdf " + (dir / "x.urdf").string() +
                                     " --mjcf " + (dir / "x.xml").string()}) {
    Outcome b = bestiary("export " + bad);
    EXPECT_EQ(b.code, 2) << bad;
    EXPECT_EQ(std::count(b.err.begin(), b.err.end(), '\n'), 1) << b.err;
  }
  EXPECT_FALSE(fs::exists(dir / "x.urdf"));
  EXPECT_FALSE(fs::exists(dir / "x.xml"));
}

TEST_F(ExportMjcf, WhatCannotBeExportedIsRefusedInOneLine) {
  const std::string c = bxtest::creature("centipede.json");
  for (const std::string& bad : {c + " --mjcf " + (dir / "x.json").string(),   // not .xml
                                 c,                                             // nothing to write
                                 c + " --mjcf " + (dir / "x.xml").string() + " --csv " + dir.string(),  // both
                                 (dir / "none.json").string() + " --mjcf " + (dir / "x.xml").string()}) {
    Outcome r = bestiary("export " + bad);
    EXPECT_EQ(r.code, 2) << bad;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  EXPECT_FALSE(fs::exists(dir / "x.xml"));
  EXPECT_FALSE(fs::exists(dir / "x.json"));
}

}  // namespace
