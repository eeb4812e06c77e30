#include <gtest/gtest.h>

#include <set>

#include "core/naming.hpp"

namespace haptex {
namespace {

TEST(MaterialId, AsciiNamesDifferingInCaseSpacesAndPunctuationAreOne) {
  EXPECT_EQ(material_id("Brick 2"), "brick_2");
  EXPECT_EQ(material_id("BRICK-2"), "brick_2");
  EXPECT_EQ(material_id("  brick__2 "), "brick_2");
  EXPECT_EQ(material_id("Sandpaper-100"), "sandpaper_100");
  EXPECT_EQ(material_id("!!"), "");
}

// Review 5: "木材 1" and "金属 1" both became "1", "Café 1" and "Cafè 1" both "caf_1", and extract
// and convert merged each pair into one material without a word.
TEST(MaterialId, NamesDifferingInLettersBeyondAsciiStayApart) {
  EXPECT_EQ(material_id("\u6728\u6750 1"), "u6728_u6750_1");
  EXPECT_EQ(material_id("\u91d1\u5c5e 1"), "u91d1_u5c5e_1");
  EXPECT_EQ(material_id("Caf\u00e9 1"), "caf_u00e9_1");
  EXPECT_EQ(material_id("Caf\u00e8 1"), "caf_u00e8_1");
  EXPECT_EQ(material_id("\u65e5\u672c"), "u65e5_u672c") << "a name without ASCII letters has an id too";
  const std::set<std::string> ids{material_id("\u6728\u6750 1"), material_id("\u91d1\u5c5e 1"), material_id("Caf\u00e9 1"),
                                  material_id("Caf\u00e8 1"), material_id("Cafe 1")};
  EXPECT_EQ(ids.size(), 5u);
}

TEST(MaterialId, CaseFoldsInLatinGreekAndCyrillicToo) {
  EXPECT_EQ(material_id("CAF\u00c9 1"), material_id("Caf\u00e9 1"));
  EXPECT_EQ(material_id("\u0141\u00d3D\u0179"), material_id("\u0142\u00f3d\u017a"));  // ŁÓDŹ, łódź
  EXPECT_EQ(material_id("\u0394\u0395\u03a1\u039c\u0391"), material_id("\u03b4\u03b5\u03c1\u03bc\u03b1"));  // ΔΕΡΜΑ, δερμα
  EXPECT_EQ(material_id("\u041a\u041e\u0416\u0410"), material_id("\u043a\u043e\u0436\u0430"));  // КОЖА, кожа
  EXPECT_EQ(material_id("\u0401\u041b\u041a\u0410"), material_id("\u0451\u043b\u043a\u0430"));  // ЁЛКА, ёлка
}

TEST(MaterialId, SpacesPunctuationAndInvisibleCharactersBeyondAsciiSeparate) {
  EXPECT_EQ(material_id("Brick\u00a02"), "brick_2");            // no-break space
  EXPECT_EQ(material_id("Brick \u2013 2"), "brick_2");          // en dash
  EXPECT_EQ(material_id("\u300cBrick\u300d\u30002"), "brick_2");  // CJK brackets, ideographic space
  EXPECT_EQ(material_id("Bri\u200bck 2\u202e"), "bri_ck_2");     // zero-width space, RLO
  EXPECT_EQ(material_id("Brick\uff082\uff09"), "brick_2");       // fullwidth parentheses
}

TEST(MaterialId, AnIdIsItsOwnId) {
  for (const char* name : {"Brick 2", "Caf\u00e9 1", "\u6728\u6750 1", "\u0141\u00f3d\u017a", "a\U0001F600b", "Wove\u0301n 1"}) {
    const std::string id = material_id(name);
    EXPECT_EQ(material_id(id), id) << name;
    EXPECT_EQ(id.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789_"), std::string::npos) << id;
  }
}

}  // namespace
}  // namespace haptex
