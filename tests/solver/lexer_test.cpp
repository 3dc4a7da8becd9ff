#include "solver/parse/lexer.h"

#include <gtest/gtest.h>

using namespace solver;
using namespace solver::parse;

TEST(Lexer, NumbersWordsStringsAndComments)
{
    Diagnostics d("t.pad");
    auto t = tokenizeLine("C 2 T 1 LL .200 UL -.2 QI 1e-3 NAME \"LEVANTE \\\"PLUMA\\\"\" // comment", 7, d);
    ASSERT_EQ(t.size(), 12u);
    EXPECT_TRUE(t[0].is("C"));
    EXPECT_TRUE(t[1].isNumber());
    EXPECT_DOUBLE_EQ(t[5].number, 0.2);
    EXPECT_DOUBLE_EQ(t[7].number, -0.2);
    EXPECT_DOUBLE_EQ(t[9].number, 1e-3);
    EXPECT_TRUE(t[11].isString());
    EXPECT_EQ(t[11].text, "LEVANTE \"PLUMA\"");
    EXPECT_EQ(t[11].pos, (SourcePos{7, 37}));
    EXPECT_TRUE(d.empty());
}

TEST(Lexer, HashCommentAndCommentGluedToToken)
{
    Diagnostics d;
    auto t = tokenizeLine("B 1 2.5// glued", 1, d);
    ASSERT_EQ(t.size(), 3u);
    EXPECT_DOUBLE_EQ(t[2].number, 2.5);
    EXPECT_TRUE(tokenizeLine("   # only a comment", 2, d).empty());
}

TEST(Lexer, ColumnsCountCharactersNotBytes)
{
    Diagnostics d;
    auto t = tokenizeLine("B 1 NAME \"muñeca\" CG", 3, d);
    ASSERT_EQ(t.size(), 5u);
    EXPECT_EQ(t[4].pos.column, 19);  // ñ is one character, two bytes
}

TEST(Lexer, NumberProblems)
{
    EXPECT_EQ(numberProblem("4,38325"), "decimal-comma");
    EXPECT_EQ(numberProblem("-0,5"), "decimal-comma");
    EXPECT_EQ(numberProblem("nan"), "not-finite");
    EXPECT_EQ(numberProblem("-Inf"), "not-finite");
    EXPECT_EQ(numberProblem("1e999"), "out-of-range");
    EXPECT_EQ(numberProblem("1e-999"), "");  // underflows to 0, still a number
    EXPECT_EQ(numberProblem("abc"), "");
    EXPECT_EQ(numberProblem("1,2,3"), "");
}

TEST(Lexer, UnterminatedStringAndControlCharacter)
{
    Diagnostics d("m.pad");
    auto t = tokenizeLine("B 1 NAME \"open", 4, d);
    ASSERT_EQ(d.size(), 1u);
    EXPECT_EQ(d.items()[0].code, "unterminated-string");
    EXPECT_EQ(d.items()[0].pos, (SourcePos{4, 10}));
    tokenizeLine("B\x01 1", 5, d);
    ASSERT_EQ(d.size(), 2u);
    EXPECT_EQ(d.items()[1].code, "control-character");
    EXPECT_EQ(d.items()[1].pos, (SourcePos{5, 2}));
}
