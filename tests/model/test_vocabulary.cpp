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

// A matrix with every kind of command target: cause 1 (two tags, one also a
// bypass tag of cause 2, so the InputTable lists it first), a comment cause,
// cause 2, effect 5 (two outputs) and a comment effect.
Matrix command_targets() {
  Matrix m;
  Cause c2;
  c2.id = 2;
  c2.tags = {{"B_IN", false, true}};
  c2.bypass_tag = "a_in";
  Cause comment;
  comment.id = 3;
  comment.function = CauseFunction::Comment;
  comment.tags = {{"C_IN", false, true}};
  Cause c1;
  c1.id = 1;
  c1.function = CauseFunction::Or;
  c1.tags = {{"A_IN", false, true}, {"Cause[2]", false, true}};
  m.causes = {c1, c2, comment};
  Effect e5;
  e5.id = 5;
  e5.tags = {{"XV_2", false}, {"XV_1", false}};
  Effect dead;
  dead.id = 6;
  dead.function = EffectFunction::Comment;
  dead.tags = {{"XV_9", false}};
  m.effects = {e5, dead};
  return m;
}

Command op(CommandOp o, int cause = 0, int effect = 0) {
  Command c;
  c.op = o;
  c.cause = cause;
  c.effect = effect;
  return c;
}

std::string text(const std::vector<Command>& cmds) {
  std::string out;
  for (const auto& c : cmds) {
    out += std::string(out.empty() ? "" : " ") + to_string(c.op);
    if (c.cause) out += " c" + std::to_string(c.cause);
    if (c.effect) out += " e" + std::to_string(c.effect);
    if (c.tag) out += " t" + std::to_string(c.tag);
    if (c.group) out += " g" + std::to_string(c.group);
    if (!c.tag_name.empty()) out += " " + c.tag_name + "=" + std::to_string(static_cast<int>(c.value));
    if (c.op == CommandOp::SoftBypassCause || c.op == CommandOp::SoftBypassTag ||
        c.op == CommandOp::SoftBypassEffect)
      out += c.on ? " on" : " off";
    out += ";";
  }
  return out;
}

// O.8's simulatable tags in the fixed order: external cause input tags in
// InputTable order (A_IN, first written as a_in), then outputs by effect and
// position; internal references, control tags and comment elements are not.
TEST(CommandOrder, SimulatableTagsInputsInTableOrderThenOutputs) {
  CommandOrder order(command_targets());
  EXPECT_EQ(order.simulatable_tags(), (std::vector<std::string>{"A_IN", "B_IN", "XV_2", "XV_1"}));
}

// Every group of docs/encoding.md "Operator commands" in its place, whatever
// order the cycle gave them in.
TEST(CommandOrder, CanonicalIsTheFixedOrder) {
  CommandOrder order(command_targets());
  Command sim = op(CommandOp::SimulateTag), stop = op(CommandOp::StopSimulation);
  sim.tag_name = "xv_1";
  sim.value = 1;
  stop.tag_name = "A_IN";
  Command sbt = op(CommandOp::SoftBypassTag, 1), sbc = op(CommandOp::SoftBypassCause, 2),
          sbe = op(CommandOp::SoftBypassEffect, 0, 5), cfo = op(CommandOp::ClearFirstOut);
  sbt.tag = 2;
  sbc.on = false;
  cfo.group = 15;
  std::vector<Command> given = {op(CommandOp::StopOverride, 0, 5), op(CommandOp::AckCause, 1),
                                op(CommandOp::ClearAlarms, 2, 5), cfo, sbe, sbt, sbc,
                                op(CommandOp::StopSimulation), stop, sim,
                                op(CommandOp::ResetEffect, 0, 5)};
  EXPECT_EQ(text(order.canonical(given)),
            "simulate_tag xv_1=1; stop_simulation A_IN=0; stop_simulation; "
            "soft_bypass_cause c2 off; soft_bypass_tag c1 t2 on; soft_bypass_effect e5 on; "
            "clear_first_out g15; clear_alarms c2; clear_alarms e5; ack_cause c1; "
            "reset_effect e5; stop_override e5;");
  for (std::size_t i = 1; i < given.size(); ++i) {
    auto a = order.rank(given[i]), b = order.rank(given[i - 1]);
    if (a && b) {
      EXPECT_NE(*a, *b);
    }
  }
}

// A set: a repeat keeps the last one (value and spelling); on and off are two
// commands; a command naming nothing of the matrix (comment elements, a tag
// position or tag the matrix lacks, group 16) ranks after all others.
TEST(CommandOrder, CanonicalKeepsTheLastRepeatAndPutsUnknownTargetsLast) {
  CommandOrder order(command_targets());
  Command a = op(CommandOp::SimulateTag), b = a;
  a.tag_name = "B_IN";
  a.value = 1;
  b.tag_name = "b_in";
  b.value = 0;
  Command on = op(CommandOp::SoftBypassCause, 1), off = on;
  off.on = false;
  Command bad_tag = op(CommandOp::SoftBypassTag, 1), no_group = op(CommandOp::ClearFirstOut),
          unknown = op(CommandOp::SimulateTag);
  bad_tag.tag = 3;
  no_group.group = 16;
  unknown.tag_name = "C_IN";  // read only by a comment cause
  EXPECT_FALSE(order.rank(bad_tag));
  EXPECT_FALSE(order.rank(no_group));
  EXPECT_FALSE(order.rank(unknown));
  EXPECT_FALSE(order.rank(op(CommandOp::AckCause, 3)));
  EXPECT_FALSE(order.rank(op(CommandOp::ResetEffect, 0, 6)));
  EXPECT_EQ(text(order.canonical({op(CommandOp::AckCause, 3), off, bad_tag, a, on, no_group, unknown, b,
                                  op(CommandOp::ResetEffect, 0, 6)})),
            "simulate_tag b_in=0; soft_bypass_cause c1 on; soft_bypass_cause c1 off; "
            "ack_cause c3; reset_effect e6; soft_bypass_tag c1 t3 on; simulate_tag C_IN=0; "
            "clear_first_out g16;");
}

TEST(Commands, NamesRoundTrip) {
  for (auto op : {CommandOp::AckCause, CommandOp::SoftBypassTag, CommandOp::ClearAlarms}) {
    auto back = command_op_from_string(to_string(op));
    ASSERT_TRUE(back);
    EXPECT_EQ(*back, op);
  }
  EXPECT_FALSE(command_op_from_string("ack"));
}
