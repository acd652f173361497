// A matrix that sets every field of cemv-matrix/1 to a non-default value (and
// texts that need CSV quoting), shared by the CSV and report tests.
#pragma once

#include "model/matrix.hpp"

namespace cemv::model::testing {

inline Matrix every_field_matrix() {
  Matrix m;
  m.name = "RT_ALL";
  m.title = "Round trip, every field; \"quoted\" title";
  m.cycle_ms = 50;
  m.sif_groups = {{1, "Level, high"}, {2, "Pressure \"PT\"; trip"}, {64, "Last"}};
  m.secure_write = SecureWrite{"EN_SWC"};
  m.group_deactivation = GroupDeactivation{"EN_GDM", "SET_GDM"};

  Cause c1;
  c1.id = 1;
  c1.name = "LT100_HH";
  c1.description = "Tank level high-high, \"A\"; B";
  c1.sil = 2;
  c1.input = InputKind::Analog;
  c1.function = CauseFunction::TwoOoThree;
  c1.tags = {{"LT_100A", true, false}, {"LT_100B", false, true}, {"LT 100C", false, true}};
  c1.analog = AnalogParams{LimitType::High, 0.1f, 0.3f, 0.05f, 0.001f, "%"};
  c1.bad_quality = BadQuality::Degrade;
  c1.time = {TimeMode::OnDelay, 2000};
  c1.auto_ack = false;
  c1.soft_bypass = {true, 3600, 3000};
  c1.bypass_tag = "HS_100_BYP";
  c1.inhibit_tag = "INH 100";
  c1.first_out_group = 3;
  c1.mutually_locked_maintenance = true;
  c1.sif = {1, 2};
  c1.note = "note with ; and , and \"quotes\" and 'single'";

  Cause c2;
  c2.id = 2;
  c2.name = "PS_AND";
  c2.description = " leading and trailing blanks ";
  c2.function = CauseFunction::And;
  c2.tags = {{"PS_1", false, true}, {"PS_2", true, false}};
  c2.time = {TimeMode::OffDelay, 500};
  c2.soft_bypass = {false, 0, 0};
  c2.bad_quality = BadQuality::Ignore;
  c2.sil = 3;

  Cause c3;
  c3.id = 3;
  c3.name = "REF_OR";
  c3.function = CauseFunction::Or;
  c3.tags = {{"Cause[1]", false, true}, {"Effect[2][1]", false, true}, {"ZS_3", false, true}};
  c3.time = {TimeMode::Timed, 1000};
  c3.sif = {64};

  Cause c4;
  c4.id = 4;
  c4.name = "LT_LOW";
  c4.input = InputKind::Analog;
  c4.tags = {{"LT_200", false, true}};
  c4.analog = AnalogParams{LimitType::Low, -12.5f, 0.0f, std::nullopt, 0.0f, ""};
  c4.first_out_group = 15;

  Cause c5;
  c5.id = 7;
  c5.name = "COMMENT_ONLY";
  c5.description = "Comment line";
  c5.function = CauseFunction::Comment;
  c5.tags = {{"DUMMY", false, true}};

  m.causes = {c1, c2, c3, c4, c5};

  Effect e1;
  e1.id = 1;
  e1.name = "CLOSE_INLET";
  e1.description = "Close inlet valve XV-101, \"fast\"";
  e1.sil = 2;
  e1.tags = {{"XV_101", false}, {"XV_102", true}};
  e1.output_delay_ms = 1500;
  e1.soft_bypass_allowed = true;
  e1.bypass_tag = "HS_101_BYP";
  e1.reset_tag = "HS_101_RST";
  e1.override_time = Override{600, 540};
  e1.process_data = ProcessData{"XV_101_BPCS", true, "XV_101_MASK"};
  e1.mutually_locked_maintenance = true;
  e1.sif = {1};
  e1.note = "effect note; with \"quotes\"";

  Effect e2;
  e2.id = 2;
  e2.name = "ALARM";
  e2.function = EffectFunction::Normal;
  e2.tags = {{"XA_1", false}};
  e2.process_data = ProcessData{std::nullopt, false, std::nullopt};

  Effect e3;
  e3.id = 5;
  e3.name = "NOTE_COLUMN";
  e3.function = EffectFunction::Comment;
  e3.tags = {{"XN_5", false}};
  e3.override_time = Override{10, 0};

  m.effects = {e1, e2, e3};

  m.intersections = {
      {1, 1, IntersectionType::V, 2, "(1) override with cabinet switch; \"main\""},
      {1, 2, IntersectionType::N, std::nullopt, ""},
      {2, 1, IntersectionType::V, 2, ""},
      {2, 5, IntersectionType::Note, std::nullopt, "note only, not processed"},
      {3, 1, IntersectionType::V, 2, ""},
      {3, 2, IntersectionType::S, std::nullopt, ""},
      {4, 2, IntersectionType::R, std::nullopt, "(2)"},
      {7, 5, IntersectionType::X, std::nullopt, ""},
  };
  return m;
}

}  // namespace cemv::model::testing
