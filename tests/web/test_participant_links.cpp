// Participant lists and tokens: the experimenter's CSV read strictly, issued tokens unguessable.
#include <gtest/gtest.h>

#include <set>

#include "studyapp/web/participant_links.hpp"
#include "studyapp/web/web_token.hpp"
#include "support/test_util.hpp"
#include "synthesis/input_error.hpp"

namespace ms::test {
namespace {

std::string problem(const TempDir& dir, const std::string& text) {
  try {
    web::read_participant_list(dir.write("list.csv", text));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ParticipantLinks, IssuedTokensAre128RandomBitsInHex) {
  std::set<std::string> seen;
  for (int i = 0; i < 200; ++i) {
    const std::string t = web::new_token();
    EXPECT_TRUE(web::token_shaped(t)) << t;
    EXPECT_EQ(t.size(), 32u);
    seen.insert(t);
  }
  EXPECT_EQ(seen.size(), 200u);
  EXPECT_FALSE(web::token_shaped(std::string(31, 'a')));
  EXPECT_FALSE(web::token_shaped(std::string(32, 'A')));    // upper case is not how tokens are written
  EXPECT_FALSE(web::token_shaped("../" + std::string(32, 'a')));
}

TEST(ParticipantLinks, AListWrittenByServeReadsBackTheSame) {
  TempDir dir;
  const auto links = web::issue_participants(3);
  EXPECT_EQ(links[2].participant, "web-003");
  web::write_participant_list(dir.file("links.csv"), links);
  const auto back = web::read_participant_list(dir.file("links.csv"));
  ASSERT_EQ(back.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(back[i].participant, links[i].participant);
    EXPECT_EQ(back[i].token, links[i].token);
  }
}

TEST(ParticipantLinks, EveryBadRowIsOneLocatedLine) {
  TempDir dir;
  const std::string t1(32, 'a'), t2(32, 'b');
  EXPECT_NE(problem(dir, "who,key\nP1," + t1 + "\n").find("list.csv:1:1: the header must be participant,token"),
            std::string::npos);
  EXPECT_NE(problem(dir, "participant,token\nP1,1234\n").find("list.csv:2:4: a token must be 32 to 128 hex digits"),
            std::string::npos);
  EXPECT_NE(problem(dir, "participant,token\nP1," + t1 + "\np1," + t2 + "\n").find("list.csv:3:1: participant 'p1' is listed twice"),
            std::string::npos);
  EXPECT_NE(problem(dir, "participant,token\nP1," + t1 + "\nP2," + t1 + "\n").find("list.csv:3:4: this token is listed twice"),
            std::string::npos);
  EXPECT_NE(problem(dir, "participant,token\n").find("no participants listed"), std::string::npos);
  EXPECT_EQ(problem(dir, "participant,token\r\n\"P 1\"," + t1 + "\r\n"), "");  // a spreadsheet's CRLF and quotes
}

}  // namespace
}  // namespace ms::test
