// Motif files: the river crossing's motif as a file a config names
// (motif.file), shipped ones built into the binary, a run's `best --out`
// file read the same way; the config records the file's hash (motif.hash);
// a bad file is refused naming the file, the field and the value.
#include "eval/motif_file.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "brain/river/found_motif.h"
#include "core/files.h"
#include "core/hash.h"
#include "io/config.h"

namespace bx {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const std::string kShippedPath = std::string(BESTIARY_SOURCE_DIR) + "/motifs/stanton2015-found.json";

// a fresh folder for the files a test writes
class MotifFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = fs::temp_directory_path() / ("bx_motif_file_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  void TearDown() override { fs::remove_all(dir); }
  std::string write(const std::string& name, const std::string& text) {
    std::ofstream(dir / name) << text;
    return (dir / name).string();
  }
  // the shipped file's JSON, for variations of it
  static json shipped() { return json::parse(*read_file(kShippedPath)); }
  fs::path dir;
};

TEST_F(MotifFileTest, TheShippedFileIsTheFoundMotifAndItsHashIsItsTextsOnDisk) {
  auto m = read_motif_file("stanton2015-found", MotifGeneDef{});
  ASSERT_TRUE(m.ok()) << m.error();
  EXPECT_EQ(m->motif, found_motif());  // exactly: river results do not change
  EXPECT_EQ(m->genes.size(), 15u);
  // built into the binary byte for byte: its hash is the file's
  auto text = read_file(kShippedPath);
  ASSERT_TRUE(text.ok()) << text.error();
  EXPECT_EQ(m->hash, fnv1a64_hex(*text));
  EXPECT_EQ(m->hash.size(), 16u);
  ASSERT_EQ(shipped_motifs().size(), 1u);
  EXPECT_EQ(shipped_motifs()[0].text, *text);
  // and read as a path, the same
  auto by_path = read_motif_file(kShippedPath, MotifGeneDef{});
  ASSERT_TRUE(by_path.ok()) << by_path.error();
  EXPECT_EQ(by_path->motif, found_motif());
  EXPECT_EQ(by_path->hash, m->hash);
}

TEST_F(MotifFileTest, AConfigNamingItGetsItsValuesAndRecordsItsHash) {
  auto cfg = read_run_config("[motif]\nfile = \"stanton2015-found\"\n", "r.toml");
  ASSERT_TRUE(cfg.ok()) << cfg.error();
  EXPECT_EQ(cfg->sim.motif, found_motif());
  EXPECT_EQ(cfg->sim.motif_source.file, "stanton2015-found");
  EXPECT_EQ(cfg->sim.motif_source.hash, fnv1a64_hex(*read_file(kShippedPath)));
  // the resolved config (what a run stores) says the values, the file and
  // the hash, and reads back as the same config without the file
  const std::string text = config_to_toml(*cfg);
  EXPECT_NE(text.find("\nfile = \"stanton2015-found\"\nhash = \"" + cfg->sim.motif_source.hash + "\"\n"),
            std::string::npos)
      << text;
  auto back = read_run_config(text, "config.toml");
  ASSERT_TRUE(back.ok()) << back.error();
  EXPECT_EQ(back->sim, cfg->sim);
  // a record keeps its motif whatever the file now holds: another file's
  // name with the recorded values and hash reads nothing
  std::string moved = text;
  moved.replace(moved.find("file = \"stanton2015-found\""), 26, "file = \"" + (dir / "gone.json").string() + "\"");
  auto kept = read_run_config(moved, "config.toml");
  ASSERT_TRUE(kept.ok()) << kept.error();
  EXPECT_EQ(kept->sim.motif, found_motif());
  // a --set of a motif value after it: the motif is no longer the file's
  auto edited = read_run_config(text, "config.toml", {"motif.tau=[1, 1, 1]"});
  ASSERT_TRUE(edited.ok()) << edited.error();
  EXPECT_EQ(edited->sim.motif_source, MotifSource{});
  EXPECT_EQ(edited->sim.motif.w, found_motif().w);
  // --set motif.file over a record reads the file named
  const std::string mine = write("mine.json", shipped().dump());
  auto reread = read_run_config(text, "config.toml", {"motif.file=" + mine});
  ASSERT_TRUE(reread.ok()) << reread.error();
  EXPECT_EQ(reread->sim.motif_source.file, mine);
  EXPECT_EQ(reread->sim.motif_source.hash, fnv1a64_hex(shipped().dump()));
  // old configs that give the values as keys still load, with no file
  auto old = read_run_config("[motif]\ntau = [1, 0.5, 0.25]\n", "old.toml");
  ASSERT_TRUE(old.ok()) << old.error();
  EXPECT_EQ(old->sim.motif.tau[1], 0.5);
  EXPECT_EQ(old->sim.motif_source, MotifSource{});
}

TEST_F(MotifFileTest, AGenotypeFileOfMotifGenesIsAMotifFile) {
  // what `best --out` writes for a motif run: genes and a provenance
  json j = shipped();
  j.erase("motif");
  j["genes"][0] = 0.5;
  j["provenance"] = {{"run", "runs/m"}, {"seed", "3"}, {"config", "[genotype]\nkind = \"motif\"\n"}};
  const std::string path = write("best.json", j.dump(2));
  auto m = read_motif_file(path, MotifGeneDef{});
  ASSERT_TRUE(m.ok()) << m.error();
  std::vector<double> genes = j["genes"].get<std::vector<double>>();
  EXPECT_EQ(m->motif, *motif_from_genes(genes, MotifGeneDef{}));
  EXPECT_EQ(m->motif.w[0][0], 8);  // gene 0 times weight_max 16
  auto cfg = read_run_config("", "r.toml", {"genotype.kind=river", "motif.file=" + path});
  ASSERT_TRUE(cfg.ok()) << cfg.error();
  EXPECT_EQ(cfg->sim.motif, m->motif);
}

TEST_F(MotifFileTest, BadFilesAreRefusedNamingTheFileTheFieldAndTheValue) {
  const auto refused = [&](const std::string& file) {
    auto cfg = read_run_config("[motif]\nfile = \"" + file + "\"\n", "r.toml");
    EXPECT_FALSE(cfg.ok()) << file;
    return cfg.ok() ? std::string() : cfg.error();
  };
  EXPECT_EQ(refused("stanton2015-fund"),
            "r.toml: motif.file: \"stanton2015-fund\": no shipped motif of that name (did you mean "
            "\"stanton2015-found\"?) (shipped: stanton2015-found) and no such file");
  EXPECT_EQ(refused(dir.string()), "r.toml: motif.file: " + dir.string() + ": not a regular file");
  const std::string not_json = write("bad.json", "genes = [1, 2]\n");
  EXPECT_EQ(refused(not_json).rfind("r.toml: motif.file: " + not_json + ": line 1, column 1 (byte 1): invalid JSON", 0),
            0u)
      << refused(not_json);
  json j = shipped();
  j["genes"].erase(14);
  const std::string short_genes = write("short.json", j.dump());
  EXPECT_EQ(refused(short_genes), "r.toml: motif.file: " + short_genes + ": genes: motif genes: 14 given, 15 expected");
  j = shipped();
  j["genes"][3] = 1.5;
  const std::string out_of_box = write("box.json", j.dump());
  EXPECT_EQ(refused(out_of_box),
            "r.toml: motif.file: " + out_of_box + ": genes: motif genes: gene 3 is 1.5, not a finite number in [-1, 1]");
  j = shipped();
  j["motif"]["tau"][1] = 0.4;
  const std::string edited = write("edited.json", j.dump());
  EXPECT_EQ(refused(edited), "r.toml: motif.file: " + edited +
                                 ": motif.tau: [1.7837384832752037, 0.4, 0.19103254352260157], but the genes give "
                                 "[1.7837384832752037, 0.39452987811361484, 0.19103254352260157]");
  j = shipped();
  j["motif"]["fitness"] = 0.95;
  const std::string bragging = write("bragging.json", j.dump());
  EXPECT_EQ(refused(bragging).rfind("r.toml: motif.file: " + bragging + ": motif.fitness: 0.95, but the genes score 0.89", 0),
            0u)
      << refused(bragging);
  j = shipped();
  j["motif"]["period"] = 1;
  const std::string unknown = write("unknown.json", j.dump());
  EXPECT_EQ(refused(unknown), "r.toml: motif.file: " + unknown +
                                  ": motif.period: unknown field (about, w, tau, alpha, input, output, fitness, "
                                  "oscillation, quiescence)");
  const std::string graph = std::string(BESTIARY_SOURCE_DIR) + "/creatures/box.json";
  EXPECT_EQ(refused(graph), "r.toml: motif.file: " + graph +
                                ": kind: a graph genotype, not a motif's genes (expected \"kind\": \"floats\" with 15 genes)");
}

TEST_F(MotifFileTest, TheMotifKeysRulesAreRefusedNamingTheKey) {
  auto both = read_run_config("[motif]\nfile = \"stanton2015-found\"\ntau = [1, 1, 1]\n", "r.toml");
  ASSERT_FALSE(both.ok());
  EXPECT_EQ(both.error(),
            "r.toml: motif.tau: given beside motif.file \"stanton2015-found\", which gives the motif (give one or the "
            "other)");
  auto hash_alone = read_run_config("", "r.toml", {"motif.hash=0123456789abcdef"});
  ASSERT_FALSE(hash_alone.ok());
  EXPECT_EQ(hash_alone.error(),
            "--set motif.hash=0123456789abcdef: motif.hash: \"0123456789abcdef\" without motif.file (the reader "
            "writes it, with the file it read)");
  auto partial = read_run_config("[motif]\nfile = \"stanton2015-found\"\nhash = \"0123456789abcdef\"\n", "r.toml");
  ASSERT_FALSE(partial.ok());
  EXPECT_EQ(partial.error(),
            "r.toml: motif.w0: not given beside motif.file and motif.hash (a resolved config gives every motif key; "
            "drop motif.hash to read motif.file again)");
  auto control = read_run_config("", "r.toml", {"motif.file=\"a\\tb\""});
  ASSERT_FALSE(control.ok());
  EXPECT_EQ(control.error(), "--set motif.file=\"a\\tb\": motif.file: expected one line of text without control "
                             "characters, got \"a\\tb\"");
}

}  // namespace
}  // namespace bx
