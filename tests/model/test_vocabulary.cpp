#include <gtest/gtest.h>

#include "model/vocabulary.hpp"

using namespace cemv::model;

TEST(InternalRef, ParsesTheThreeFormsOf613) {
  auto c = parse_internal_ref("Cause[12]");
  ASSERT_TRUE(c);
  EXPECT_EQ(c->kind, InternalRef::Kind::Cause);
  EXPECT_EQ(c->id, 12);
  auto e = parse_internal_ref("Effect[3]");
  ASSERT_TRUE(e);
  EXPECT_EQ(e->kind, InternalRef::Kind::Effect);
  auto et = parse_internal_ref("Effect[3][2]");
  ASSERT_TRUE(et);
  EXPECT_EQ(et->kind, InternalRef::Kind::EffectTag);
  EXPECT_EQ(et->id, 3);
  EXPECT_EQ(et->tag, 2);
}

TEST(InternalRef, RejectsLookalikes) {
  for (const char* s : {"Cause", "Cause[]", "Cause[1][2]", "cause[1]", "Cause[x]", "Effect[1]x",
                        "Effect[1][", "Cause[-1]", "Cause[1234]", "LT_100"})
    EXPECT_FALSE(parse_internal_ref(s)) << s;
}

TEST(InputTable, CollectsExternalTagsOnceCaseInsensitively) {
  Matrix m;
  Cause c;
  c.id = 1;
  c.input = InputKind::Analog;
  c.function = CauseFunction::Or;
  c.tags = {{"LT_1", false, true}, {"lt_1", false, true}, {"Effect[2]", false, true}};
  c.bypass_tag = "HS_BYP";
  m.causes.push_back(c);
  Effect e;
  e.id = 2;
  e.tags = {{"XV_1", false}};
  e.reset_tag = "hs_byp";
  m.effects.push_back(e);
  InputTable t(m);
  ASSERT_EQ(t.size(), 2u);
  EXPECT_EQ(t.tags()[0].name, "LT_1");
  EXPECT_EQ(t.tags()[0].kind, TagKind::Analog);
  EXPECT_EQ(t.tags()[1].roles.size(), 2u);
  EXPECT_EQ(t.find("Lt_1"), 0u);
  EXPECT_EQ(t.find("HS_byp"), 1u);
  EXPECT_FALSE(t.find("XV_1"));  // outputs are not inputs
}

TEST(Commands, NamesRoundTrip) {
  for (auto op : {CommandOp::AckCause, CommandOp::SoftBypassTag, CommandOp::ClearAlarms}) {
    auto back = command_op_from_string(to_string(op));
    ASSERT_TRUE(back);
    EXPECT_EQ(*back, op);
  }
  EXPECT_FALSE(command_op_from_string("ack"));
}
