#include "roughContact/asperity/Hertz.hpp"
#include <gtest/gtest.h>
TEST(Hertz, placeholder) { roughContact::Hertz h(1.0); EXPECT_GT(h.areaAtForce(1.0, 1.0), 0.0); }
