// The river crossing's genome layout: its count, and genes 0, 1, 2, ...
// landing in the paper's order, matrix after matrix, row after row.
#include "brain/river/river_genome.h"

#include <gtest/gtest.h>

#include <numeric>
#include <string>
#include <vector>

namespace bx {
namespace {

std::vector<double> counting(int n) {
  std::vector<double> g(static_cast<std::size_t>(n));
  std::iota(g.begin(), g.end(), 0.0);
  return g;
}

TEST(RiverGenome, CountForAShape) {
  // DN 6x4 + 5x4, PN 8x4 + 5x4, PG 5x5, motors 12x5
  EXPECT_EQ(river_gene_count(RiverShape{}), 24 + 20 + 32 + 20 + 25 + 60);
  EXPECT_EQ(river_gene_count(RiverShape{}), 181);
  // DN 6x3 + 5x3, PN 8x7 + 2x7, PG 2x2, motors 4x2
  EXPECT_EQ(river_gene_count(RiverShape{3, 7, 2, 4}), 18 + 15 + 56 + 14 + 4 + 8);
}

TEST(RiverGenome, UnpackLaysGenesInThePapersOrder) {
  const RiverShape s;
  Result<RiverWeights> r = unpack_river_genes(s, counting(181));
  ASSERT_TRUE(r.ok()) << r.error();
  const RiverWeights& w = *r;

  // DN input -> hidden: genes 0..23, hidden h's six inputs together
  ASSERT_EQ(w.dn_input_hidden.rows, 4);
  ASSERT_EQ(w.dn_input_hidden.cols, 6);
  for (int h = 0; h < 4; ++h)
    for (int i = 0; i < 6; ++i) EXPECT_EQ(w.dn_input_hidden.at(h, i), h * 6 + i);
  // DN hidden -> output: 24..43
  ASSERT_EQ(w.dn_hidden_output.rows, 5);
  ASSERT_EQ(w.dn_hidden_output.cols, 4);
  for (int o = 0; o < 5; ++o)
    for (int h = 0; h < 4; ++h) EXPECT_EQ(w.dn_hidden_output.at(o, h), 24 + o * 4 + h);
  // PN input -> hidden: 44..75
  ASSERT_EQ(w.pn_input_hidden.rows, 4);
  ASSERT_EQ(w.pn_input_hidden.cols, 8);
  for (int h = 0; h < 4; ++h)
    for (int i = 0; i < 8; ++i) EXPECT_EQ(w.pn_input_hidden.at(h, i), 44 + h * 8 + i);
  // PN hidden -> output: 76..95
  ASSERT_EQ(w.pn_hidden_output.rows, 5);
  ASSERT_EQ(w.pn_hidden_output.cols, 4);
  for (int o = 0; o < 5; ++o)
    for (int h = 0; h < 4; ++h) EXPECT_EQ(w.pn_hidden_output.at(o, h), 76 + o * 4 + h);
  // PG interconnection, PN output k into motif m: 96..120
  ASSERT_EQ(w.pg_input.rows, 5);
  ASSERT_EQ(w.pg_input.cols, 5);
  for (int m = 0; m < 5; ++m)
    for (int k = 0; k < 5; ++k) EXPECT_EQ(w.pg_input.at(m, k), 96 + m * 5 + k);
  // PG -> motor, motif m into motor j: 121..180
  ASSERT_EQ(w.pg_motor.rows, 12);
  ASSERT_EQ(w.pg_motor.cols, 5);
  for (int j = 0; j < 12; ++j)
    for (int m = 0; m < 5; ++m) EXPECT_EQ(w.pg_motor.at(j, m), 121 + j * 5 + m);
  EXPECT_EQ(w.pg_motor.at(11, 4), 180);
}

TEST(RiverGenome, UnpackFollowsTheShape) {
  const RiverShape s{3, 7, 2, 4};
  Result<RiverWeights> r = unpack_river_genes(s, counting(115));
  ASSERT_TRUE(r.ok()) << r.error();
  EXPECT_EQ(r->dn_hidden_output.at(0, 0), 18);
  EXPECT_EQ(r->pn_input_hidden.at(0, 0), 33);
  EXPECT_EQ(r->pn_hidden_output.at(1, 6), 89 + 13);
  EXPECT_EQ(r->pg_input.at(1, 1), 103 + 3);
  EXPECT_EQ(r->pg_motor.at(0, 0), 107);
  EXPECT_EQ(r->pg_motor.at(3, 1), 114);
}

TEST(RiverGenome, WrongLengthIsAnErrorNamingBothCounts) {
  for (int n : {0, 180, 182}) {
    Result<RiverWeights> r = unpack_river_genes(RiverShape{}, counting(n));
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().find(std::to_string(n) + " genes given"), std::string::npos) << r.error();
    EXPECT_NE(r.error().find("181 expected"), std::string::npos) << r.error();
    EXPECT_NE(r.error().find("DN 6-4-5, PN 8-4-5, 5 motifs, 12 motors"), std::string::npos) << r.error();
  }
}

TEST(RiverGenome, BadShapeNamesTheField) {
  RiverShape s;
  s.pn_hidden = 0;
  Result<RiverWeights> r = unpack_river_genes(s, counting(181));
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().find("pn_hidden is 0"), std::string::npos) << r.error();
  s = RiverShape{};
  s.motors = -2;
  EXPECT_NE(check_river_shape(s).error().find("motors is -2"), std::string::npos);
}

}  // namespace
}  // namespace bx
