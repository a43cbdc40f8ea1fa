// placeholder, replaced below
#include <gtest/gtest.h>
TEST(Packing, Placeholder) {}
