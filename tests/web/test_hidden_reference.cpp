// What serve guarantees about a MUSHRA trial's hidden reference: it is heard exactly as the open
// reference (the same bytes), and nothing else about it (name, hash, id, metadata) points at it.
#include <set>

#include "web/serve_fixture.hpp"

namespace ms::test {
namespace {

class HiddenReferenceTest : public ServeTest {
 protected:
  nlohmann::json mushra_page(std::size_t i = 0) {
    for (nlohmann::json p = page(i); !p.value("finished", false); p = page(i)) {
      if (p["type"] == "mushra") return p;
      EXPECT_EQ(answer_current(i).status, 200);
    }
    ADD_FAILURE() << "no MUSHRA trial";
    return {};
  }
  std::vector<std::string> wavs(const nlohmann::json& p, std::size_t i = 0) const {
    std::vector<std::string> out;
    for (const auto& s : p["sounds"]) {
      const HttpReply r = get(api("sound/" + s["id"].get<std::string>(), i));
      EXPECT_EQ(r.status, 200);
      out.push_back(r.body);
    }
    return out;
  }
};

TEST_F(HiddenReferenceTest, IsServedByteIdenticalToTheOpenReferenceUnderItsOwnOpaqueId) {
  const nlohmann::json p = mushra_page();
  const std::vector<std::string> bytes = wavs(p);
  ASSERT_GE(bytes.size(), 4u);  // open reference, hidden reference, two conditions (+ anchors)
  std::size_t identical = 0;
  for (std::size_t k = 1; k < bytes.size(); ++k) identical += bytes[k] == bytes[0];
  EXPECT_EQ(identical, 1u) << "exactly one condition is the reference, sample for sample";
  std::set<std::string> ids;
  for (const auto& s : p["sounds"]) ids.insert(s["id"].get<std::string>());
  EXPECT_EQ(ids.size(), p["sounds"].size());  // the hidden reference has an id of its own
}

TEST_F(HiddenReferenceTest, TheSoundFilesCarryNoNameHashOrMetadata) {
  const nlohmann::json p = mushra_page();
  for (const std::string& wav : wavs(p)) {
    EXPECT_EQ(wav.find("zeta"), std::string::npos);
    EXPECT_EQ(wav.find("LIST"), std::string::npos);  // no INFO chunk (title, comment, software)
    for (const auto& entry : std::filesystem::directory_iterator(dir_.file("stimulus-cache")))
      EXPECT_EQ(wav.find(entry.path().stem().string()), std::string::npos);
  }
}

TEST_F(HiddenReferenceTest, IdsAreDrawnAfreshAtEverySendingAndAnOldIdIsRefused) {
  const nlohmann::json before = mushra_page();
  const std::vector<std::string> heard_before = wavs(before);
  restart();
  const nlohmann::json after = page();
  ASSERT_EQ(after["trial"], before["trial"]);
  for (std::size_t k = 0; k < before["sounds"].size(); ++k) {
    EXPECT_NE(after["sounds"][k]["id"], before["sounds"][k]["id"]);
    EXPECT_EQ(get(api("sound/" + before["sounds"][k]["id"].get<std::string>())).status, 404);
  }
  EXPECT_TRUE(wavs(after) == heard_before);  // the same sounds in the same places, only the ids changed
}

}  // namespace
}  // namespace ms::test
