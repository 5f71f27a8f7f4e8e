// Static file resolution: percent-decoding, traversal in every spelling, symbolic links, types.
#include <gtest/gtest.h>

#include <fstream>

#include <stdlib.h>

#include "net/static_files.h"

namespace geodesic::net {
namespace {

namespace fs = std::filesystem;

class StaticFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string dir = (fs::temp_directory_path() / "geodesic-static-XXXXXX").string();
    ASSERT_TRUE(mkdtemp(dir.data()));
    root_ = dir;
    fs::create_directories(web() / "docs");
    std::ofstream(root_ / "secret.txt") << "secret";
    std::ofstream(web() / "index.html") << "index";
    std::ofstream(web() / "app.js") << "js";
    std::ofstream(web() / "docs" / "index.html") << "docs";
    std::ofstream(web() / "a b.txt") << "space";
    fs::create_directory_symlink(root_, web() / "escape");
  }
  void TearDown() override { fs::remove_all(root_); }
  fs::path web() const { return root_ / "web"; }
  std::optional<std::string> body(std::string_view target) const {
    auto file = load_static_file(web(), target);
    return file ? std::optional(file->body) : std::nullopt;
  }

  fs::path root_;
};

TEST_F(StaticFiles, ServesFilesAndDirectoryIndexes) {
  EXPECT_EQ(body("/"), "index");
  EXPECT_EQ(body("/index.html"), "index");
  EXPECT_EQ(body("/docs/"), "docs");
  EXPECT_EQ(body("/docs"), "docs");
  EXPECT_EQ(body("/./app.js"), "js");
  EXPECT_EQ(body("/a%20b.txt"), "space");
  EXPECT_EQ(load_static_file(web(), "/app.js")->mime_type, "text/javascript; charset=utf-8");
  EXPECT_FALSE(body("/missing.html"));
}

TEST_F(StaticFiles, NeverLeavesTheWebDirectory) {
  for (const char* target :
       {"/../secret.txt", "/%2e%2e/secret.txt", "/%2E%2E/secret.txt", "/..%2fsecret.txt",
        "/%2e%2e%2fsecret.txt", "/docs/../../secret.txt", "/docs/%2e%2e/%2e%2e/secret.txt",
        "/..\\secret.txt", "/%5c..%5csecret.txt", "/escape/secret.txt", "/%00", "/%zz", "/%2",
        "relative.html"})
    EXPECT_FALSE(body(target)) << target;
}

TEST(PercentDecode, DecodesAndRejectsMalformedEscapes) {
  EXPECT_EQ(percent_decode("/a%2Fb%20c"), "/a/b c");
  EXPECT_EQ(percent_decode("%252e"), "%2e");  // decoded once only
  EXPECT_FALSE(percent_decode("%4"));
  EXPECT_FALSE(percent_decode("%g0"));
  EXPECT_FALSE(percent_decode("%00"));
}

TEST(MimeType, ByExtension) {
  EXPECT_EQ(mime_type("index.HTML"), "text/html; charset=utf-8");
  EXPECT_EQ(mime_type("style.css"), "text/css; charset=utf-8");
  EXPECT_EQ(mime_type("frame.jpg"), "image/jpeg");
  EXPECT_EQ(mime_type("module.wasm"), "application/wasm");
  EXPECT_EQ(mime_type("data.bin"), "application/octet-stream");
}

}  // namespace
}  // namespace geodesic::net
