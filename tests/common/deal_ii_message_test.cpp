// deal.II's exception text turned into one line: the user's part only,
// whitespace collapsed, the unbounded number pattern in words.
#include <gtest/gtest.h>

#include <string>

#include "common/deal_ii_message.h"

namespace softglass {
namespace {

// The layout of deal.II's ExceptionBase::what(): a rule, where it was thrown,
// the additional information, the stack trace and a closing rule.
std::string deal_ii_text(const std::string& information, bool stack_trace) {
  const std::string rule = "--------------------------------------------------------\n";
  std::string text = "\n" + rule +
                     "An error occurred in line <2119> of file <parameter_handler.cc> in "
                     "function\n    void dealii::ParameterHandler::set(...)\nThe violated "
                     "condition was: \n    false\nAdditional information: \n" +
                     information;
  if (stack_trace) text += "\nStacktrace:\n-----------\n#0  libdeal_II.so: ...\n";
  return text + rule;
}

TEST(DealIIMessage, KeepsTheAdditionalInformationOnOneLine) {
  const std::string information =
      "    Line <3> of file <case.prm>:\n"
      "    The entry value\n"
      "        abc\n"
      "    for the entry named\n"
      "        radius\n"
      "    does not match the given pattern\n"
      "        [Double 0...MAX_DOUBLE (inclusive)]\n";
  const std::string expected =
      "Line <3> of file <case.prm>: The entry value abc for the entry named radius does not "
      "match the given pattern [Double 0...MAX_DOUBLE (inclusive)]";
  EXPECT_EQ(deal_ii_message(deal_ii_text(information, true)), expected);
  EXPECT_EQ(deal_ii_message(deal_ii_text(information, false)), expected);
}

TEST(DealIIMessage, NamesTheUnboundedNumberPatternInWords) {
  EXPECT_EQ(deal_ii_message(deal_ii_text(
                "The string <x> does not match the pattern \"[Double -MAX_DOUBLE...MAX_DOUBLE "
                "(inclusive)]\"\n",
                true)),
            "The string <x> does not match the pattern \"a number (without units)\"");
}

TEST(DealIIMessage, OtherTextIsOnlyCollapsed) {
  EXPECT_EQ(deal_ii_message("  cannot open\tfile \n 'x.prm'  \n"), "cannot open file 'x.prm'");
  EXPECT_EQ(deal_ii_message(""), "");
}

}  // namespace
}  // namespace softglass
