// parse(print(ast)) == ast on seeded random programs of the whole subset
// (docs/plc.md P.1-P.7): every statement, operator, function, literal kind
// and block, nested.
#include <gtest/gtest.h>

#include <cstdint>

#include "formats/diagnostics.hpp"
#include "plc/check.hpp"
#include "plc/interpreter.hpp"
#include "plc/parser.hpp"
#include "plc/print.hpp"
#include "random_program.hpp"

namespace cemv::plc {
namespace {

TEST(PlcRoundTrip, RandomProgramsPrintAndReadBackTheSame) {
  for (std::uint64_t seed = 1; seed <= 300; ++seed) {
    Program p = test::Generator(seed).program();
    p.file = "random.st";
    try {
      check_program(p);
    } catch (const formats::LoadError& e) {
      FAIL() << "seed " << seed << ": the generator made a program the checker refuses: " << e.issues()[0].message()
             << "\n" << print_program(p);
    }
    const std::string text = print_program(p);
    Program back;
    try {
      back = parse_st(text, "printed.st");
    } catch (const formats::LoadError& e) {
      FAIL() << "seed " << seed << ": " << e.issues()[0].message() << "\n" << text;
    }
    ASSERT_EQ(without_positions(back), without_positions(p)) << "seed " << seed << "\n" << text << "\n----\n"
                                                             << print_program(back);
  }
}

}  // namespace
}  // namespace cemv::plc

namespace cemv::plc {
namespace {

// Random programs run on random inputs: every name resolves, nothing throws,
// and a reset run repeats the first one exactly (P.8.3).
TEST(PlcRoundTrip, RandomProgramsRunDeterministically) {
  for (std::uint64_t seed = 1; seed <= 100; ++seed) {
    Program p = test::Generator(seed).program();
    p.file = "random.st";
    check_program(p);
    Interpreter run(p);
    std::mt19937_64 rng(seed);
    std::vector<std::map<std::string, Value>> inputs;
    for (int scan = 0; scan < 20; ++scan) {
      inputs.push_back({{"b0", Value{Type::Bool, static_cast<std::int64_t>(rng() % 2), 0}},
                        {"b1", Value{Type::Bool, static_cast<std::int64_t>(rng() % 2), 0}},
                        {"i0", Value{Type::Int, static_cast<std::int64_t>(rng() % 2000) - 1000, 0}},
                        {"r0", Value{Type::Real, 0, static_cast<float>(rng() % 400) / 8.0f}},
                        {"t0", Value{Type::Time, static_cast<std::int64_t>(rng() % 5000), 0}}});
    }
    auto outputs = [&] {
      std::vector<Value> out;
      run.reset();
      for (const auto& in : inputs) {
        run.step(in, 50 + static_cast<std::int64_t>(in.at("t0").integer % 3) * 25);
        for (const char* name : {"ob", "oi", "od", "io", "ld", "lr", "lt", "TON_1.ET", "RS_1.Q1"}) out.push_back(run.value(name));
      }
      return out;
    };
    const auto first = outputs();
    EXPECT_EQ(outputs(), first) << "seed " << seed;
  }
}

}  // namespace
}  // namespace cemv::plc
