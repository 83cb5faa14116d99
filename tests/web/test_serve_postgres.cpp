// serve into a PostgreSQL store: a whole session stored on the server, resumed after a restart, and the
// local files (links, stimulus cache) where a SQLite store would have been, never in a folder named after
// the URI. Needs MODALSTUDY_TEST_POSTGRES_URL (else skipped).
#include <filesystem>

#include "support/test_stores.hpp"
#include "web/serve_fixture.hpp"

namespace ms::test {
namespace {

namespace fs = std::filesystem;

class ServePostgresTest : public ServeTest {
 protected:
  void SetUp() override {
    if (!store_.available()) GTEST_SKIP() << kNoPostgres;
    db_ = store_.location();
    ServeTest::SetUp();
  }
  TestStore store_{Backend::postgresql};
};

TEST_F(ServePostgresTest, AWholeSessionIsStoredOnTheServerAndResumedAfterARestart) {
  const std::size_t total = page()["total"];
  ASSERT_EQ(total, 5u);
  for (std::size_t n = 0; n < 3; ++n) ASSERT_EQ(answer_current().status, 200);
  EXPECT_EQ(stored("responses"), 3);
  restart();
  EXPECT_EQ(page()["position"], 4);  // the first unanswered trial
  for (std::size_t n = 3; n < total; ++n) ASSERT_EQ(answer_current().status, 200);
  EXPECT_EQ(stored("responses"), 5);
  EXPECT_TRUE(page().value("finished", false));
  // The other participant's link is untouched: nothing of theirs was stored.
  EXPECT_EQ(page(1)["position"], 1);
}

TEST_F(ServePostgresTest, LinksAndCacheLiveBesideTheProtocolNotInAFolderNamedAfterTheUri) {
  const fs::path results = fs::path(protocol_).parent_path() / "results";
  EXPECT_EQ(fs::path(server_->links_path()), results / "webtest.sqlite.links.csv");
  EXPECT_TRUE(fs::is_regular_file(server_->links_path()));
  EXPECT_TRUE(fs::is_directory(results / "stimulus-cache"));
  EXPECT_FALSE(fs::exists("postgresql:"));
  EXPECT_FALSE(fs::exists(fs::path(protocol_).parent_path() / "postgresql:"));
  const std::string first = token(0);
  restart();  // the same links after a restart
  EXPECT_EQ(token(0), first);
}

}  // namespace
}  // namespace ms::test
