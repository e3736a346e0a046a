// A genotype's file: a graph genome's is the genome file, unchanged; another
// kind's is its JSON form with its kind, format and version; both read back
// exactly, with or without a provenance, and bad files are errors naming the
// file and the field.
#include "genome/genotype_file.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "genome/float_vector.h"
#include "genome/genome_json.h"
#include "genome/graph_genotype.h"

namespace bx {
namespace {

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

Genome walker() {
  auto g = load_genome(std::string(BESTIARY_SOURCE_DIR) + "/creatures/walker.json");
  EXPECT_TRUE(g) << g.error();
  return *g;
}

TEST(GenotypeFile, AGraphGenomesFileIsTheGenomeFile) {
  const GraphGenotype g(walker());
  EXPECT_EQ(genotype_text(g), genome_to_string(g.genome));
  // as `best --out` wrote it before other kinds: the JSON form and the provenance, sorted keys
  nlohmann::json prov = {{"run", "r"}, {"seed", "7"}};
  nlohmann::json expected = genome_to_json(g.genome);
  expected["provenance"] = prov;
  EXPECT_EQ(genotype_file_string(g, prov), expected.dump(2) + "\n");
  auto back = genotype_from_file_text(genotype_file_string(g, prov), "w.json");
  ASSERT_TRUE(back) << back.error();
  EXPECT_EQ(back->get()->kind(), "graph");
  EXPECT_TRUE(back->get()->equals(g));
  // the genome file's own reader reads it too
  EXPECT_TRUE(genome_from_string(genotype_file_string(g, prov), "w.json"));
}

TEST(GenotypeFile, AGraphGenomeMayNameItsKind) {
  const std::string text = slurp(std::string(BESTIARY_SOURCE_DIR) + "/creatures/walker.json");
  std::string named = text;
  named.insert(named.find('{') + 1, "\"kind\": \"graph\",");
  auto a = genotype_from_file_text(text, "a.json"), b = genotype_from_file_text(named, "b.json");
  ASSERT_TRUE(a) << a.error();
  ASSERT_TRUE(b) << b.error();
  EXPECT_TRUE(a->get()->equals(**b));
}

TEST(GenotypeFile, AFloatVectorsFileReadsBackExactly) {
  const FloatVector v({0.1, -1.0 / 3, 1e-300, 12345.678901234567, -0.0});
  const nlohmann::json prov = {{"run", "r"}, {"seed", "7"}, {"config", "[genotype]\n"}};
  const std::string text = genotype_file_string(v, prov);
  // format, version, kind, the genes, the provenance, in that order
  const auto j = nlohmann::json::parse(text);
  EXPECT_EQ(j["format"], "bestiary-genotype");
  EXPECT_EQ(j["version"], 1);
  EXPECT_EQ(j["kind"], "floats");
  EXPECT_EQ(j["provenance"], prov);
  EXPECT_LT(text.find("\"format\""), text.find("\"kind\""));
  EXPECT_LT(text.find("\"kind\""), text.find("\"genes\""));
  EXPECT_LT(text.find("\"genes\""), text.find("\"provenance\""));
  auto back = genotype_from_file_text(text, "v.json");
  ASSERT_TRUE(back) << back.error();
  ASSERT_EQ(back->get()->kind(), "floats");
  EXPECT_EQ(static_cast<const FloatVector&>(**back).genes, v.genes);  // every bit
  EXPECT_EQ(genotype_text(**back), genotype_text(v));
  EXPECT_EQ(genotype_text(v), genotype_file_string(v));
  EXPECT_EQ(genotype_text(v).find("provenance"), std::string::npos);
  // a hand-written one needs only its kind and genes
  auto plain = genotype_from_file_text(R"({"kind": "floats", "genes": [1, 2.5]})", "p.json");
  ASSERT_TRUE(plain) << plain.error();
  EXPECT_EQ(static_cast<const FloatVector&>(**plain).genes, (std::vector<double>{1, 2.5}));
}

TEST(GenotypeFile, ErrorsNameTheFileAndTheField) {
  auto err = [](const std::string& text) {
    auto g = genotype_from_file_text(text, "x.json");
    return g ? std::string("(read)") : g.error();
  };
  EXPECT_EQ(err(R"({"kind": 3, "genes": []})"), "x.json: kind: expected a genotype kind's name (graph, floats), got 3");
  EXPECT_EQ(err(R"({"kind": "trees", "genes": []})"),
            "x.json: unknown genotype kind \"trees\" (expected graph or floats)");
  EXPECT_EQ(err(R"({"kind": "floats", "genes": [1, "a"]})"),
            "x.json: floats: genes[1]: not a finite number, got \"a\"");
  EXPECT_EQ(err(R"({"kind": "floats"})"), "x.json: floats: no field genes");
  EXPECT_EQ(err(R"({"format": "bestiary-genome", "kind": "floats", "genes": []})"),
            "x.json: format: not a genotype file (expected \"bestiary-genotype\"), got \"bestiary-genome\"");
  EXPECT_EQ(err(R"({"version": 2, "kind": "floats", "genes": []})"),
            "x.json: version: unsupported version 2 (this build reads 1), got 2");
  EXPECT_EQ(err(R"({"kind": "floats", "genes": [], "provenance": 1})"),
            "x.json: provenance: expected an object, got 1");
  EXPECT_EQ(err(R"({"kind": "floats", "genes": [], "genes": [1]})"), "x.json: genes: field given twice");
  // a file without a kind is a genome file, with its reader's errors
  EXPECT_EQ(err(R"({"genes": []})"), genome_from_string(R"({"genes": []})", "x.json").error());
}

}  // namespace
}  // namespace bx
