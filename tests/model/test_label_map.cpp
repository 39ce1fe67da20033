#include <gtest/gtest.h>

#include "model/label_map.hpp"

using inpact::model::LabelMap;

TEST(LabelMap, DenseAndSparseLabelsPerInstance) {
  LabelMap m;
  EXPECT_TRUE(m.insert(0, 1, 0));
  EXPECT_TRUE(m.insert(0, 2, 1));
  EXPECT_TRUE(m.insert(0, 1'000'000'000'000, 2));  // far beyond the dense table
  EXPECT_TRUE(m.insert(1, 1, 3));                  // same label, other instance
  EXPECT_FALSE(m.insert(0, 2, 9));
  EXPECT_FALSE(m.insert(0, 1'000'000'000'000, 9));
  EXPECT_EQ(*m.find(0, 2), 1);
  EXPECT_EQ(*m.find(0, 1'000'000'000'000), 2);
  EXPECT_EQ(*m.find(1, 1), 3);
  EXPECT_FALSE(m.find(0, 3));
  EXPECT_FALSE(m.find(2, 1));
  EXPECT_EQ(m.size(), 4u);
}

TEST(LabelMap, SmallModelWithAnOffsetPart) {
  // Two blocks numbered 1.. and 1,000,001..: the second goes to the hash, both are found.
  LabelMap m;
  for (int i = 0; i < 100; ++i) {
    EXPECT_TRUE(m.insert(0, 1 + i, i));
    EXPECT_TRUE(m.insert(0, 1'000'001 + i, 100 + i));
  }
  EXPECT_FALSE(m.insert(0, 1'000'050, 9));
  EXPECT_EQ(*m.find(0, 50), 49);
  EXPECT_EQ(*m.find(0, 1'000'050), 149);
  EXPECT_FALSE(m.find(0, 1'000'101));
  EXPECT_EQ(m.size(), 200u);
}
