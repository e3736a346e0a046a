// An ESP creature on the command line (lessin2015 IV-B): brain.skill runs
// one encapsulated skill alone, scoring what the skill scored before it was
// encapsulated; `show` puts each skill alone beside the free brain.
#include <gtest/gtest.h>

#include <string>

#include "genome/encapsulate.h"
#include "genome/genome_json.h"
#include "support/run_command.h"

namespace bx {
namespace {

class SkillsCli : public bxtest::InTempDir {
 protected:
  // the crawler with its crawl encapsulated, as a genome file
  std::string esp_crawler() {
    auto g = load_genome(bxtest::creature("lessin_crawler.json"));
    EXPECT_TRUE(g.ok()) << g.error();
    auto e = encapsulate(*g, {"crawl"});
    EXPECT_TRUE(e.ok()) << e.error();
    const std::string path = (dir / "esp.json").string();
    EXPECT_TRUE(save_genome(path, *e).ok());
    return path;
  }
  static std::string fitness_of(const std::string& out) {
    const auto at = out.find("fitness ");
    return at == std::string::npos ? "" : out.substr(at, out.find('\n', at) - at);
  }
};

TEST_F(SkillsCli, ASkillAloneScoresAsBeforeItsEncapsulationAndNothingWithoutIt) {
  const std::string esp = esp_crawler();
  const std::string opts = " --seconds 3 --set motor.response_time=0.01 --set task.drop_height=0.01";
  auto before = bxtest::bestiary("simulate " + bxtest::creature("lessin_crawler.json") + opts);
  ASSERT_EQ(before.code, 0) << before.err;
  auto alone = bxtest::bestiary("simulate " + esp + opts + " --set brain.skill=crawl");
  ASSERT_EQ(alone.code, 0) << alone.err;
  EXPECT_EQ(fitness_of(alone.out), fitness_of(before.out));
  EXPECT_NE(fitness_of(before.out), "fitness 0");
  auto free = bxtest::bestiary("simulate " + esp + opts);  // nothing drives its switch
  ASSERT_EQ(free.code, 0) << free.err;
  EXPECT_LT(std::stod(fitness_of(free.out).substr(8)), 1e-4) << free.out;  // its muscles silent: it only sags
  auto unknown = bxtest::bestiary("simulate " + esp + opts + " --set brain.skill=fly");
  EXPECT_NE(unknown.out.find("brain.skill: no skill \"fly\" in this genome (its skills: \"crawl\")"), std::string::npos)
      << unknown.out << unknown.err;
}

TEST_F(SkillsCli, ShowPutsEachSkillAloneBesideTheFreeBrain) {
  const std::string esp = esp_crawler();
  const std::string page = (dir / "esp.html").string();
  auto r = bxtest::bestiary("show " + esp + " --seconds 1 --out " + page);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("1 skill(s) each alone beside it"), std::string::npos) << r.out;
  const std::string html = bxtest::slurp(page);
  EXPECT_NE(html.find("its brain free"), std::string::npos);
  const auto alone = html.find("alone");
  ASSERT_NE(alone, std::string::npos);
  EXPECT_NE(html.substr(alone - 30, 35).find("crawl"), std::string::npos) << html.substr(alone - 30, 35);
}

}  // namespace
}  // namespace bx
