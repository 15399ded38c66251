#include <gtest/gtest.h>

#include "lepp/io.h"

namespace lepp {

TEST(ReadPoly, PaperSquare400) {
  Pslg p = read_poly(LEPP_SOURCE_DIR "/corpus/paper/square400.poly");
  EXPECT_EQ(p.vertices.size(), 400u);
  EXPECT_EQ(p.segments.size(), 400u);
  EXPECT_TRUE(p.holes.empty());
}

TEST(ReadPoly, PaperCirclesHasOneHole) {
  Pslg p = read_poly(LEPP_SOURCE_DIR "/corpus/paper/circles240.poly");
  EXPECT_EQ(p.vertices.size(), 240u);
  EXPECT_EQ(p.holes.size(), 1u);
}

}  // namespace lepp
