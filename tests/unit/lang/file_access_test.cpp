// The read rule: roots, links, and what is not a file.
#include <catch2/catch.hpp>

#include "file_access.hpp"
#include "interpreter.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

using namespace crt::lang;
namespace fs = std::filesystem;

namespace {

/// A fresh folder with root/inside.crt and outside/secret.crt.
struct Tree {
    fs::path base = fs::temp_directory_path() / ("crt-file-access-" + std::to_string(::getpid()));
    Tree() {
        fs::remove_all(base);
        fs::create_directories(base / "root" / "sub");
        fs::create_directories(base / "outside");
        std::ofstream(base / "root" / "inside.crt") << "x = 1\n";
        std::ofstream(base / "outside" / "secret.crt") << "y = 2\n";
    }
    ~Tree() { fs::remove_all(base); }
};

} // namespace

TEST_CASE("files under a root are readable, others refused whether or not they exist", "[access]") {
    Tree tree;
    FileAccess access;
    access.addRoot(tree.base / "root");
    CHECK(access.check(tree.base / "root" / "inside.crt").readable());
    CHECK(access.check(tree.base / "root" / "missing.crt").kind == FileCheck::Kind::Missing);
    CHECK(access.check(tree.base / "outside" / "secret.crt").kind == FileCheck::Kind::Outside);
    CHECK(access.check(tree.base / "outside" / "missing.crt").kind == FileCheck::Kind::Outside);
    CHECK(access.check(tree.base / "root" / ".." / "outside" / "secret.crt").kind == FileCheck::Kind::Outside);
    // "/x/rootish" is not under "/x/root".
    fs::create_directories(tree.base / "rootish");
    std::ofstream(tree.base / "rootish" / "a.crt") << "\n";
    CHECK(access.check(tree.base / "rootish" / "a.crt").kind == FileCheck::Kind::Outside);
}

TEST_CASE("a link is judged by where it leads", "[access]") {
    Tree tree;
    fs::create_symlink(tree.base / "outside" / "secret.crt", tree.base / "root" / "link.crt");
    FileAccess access;
    access.addRoot(tree.base / "root");
    const FileCheck check = access.check(tree.base / "root" / "link.crt");
    CHECK(check.kind == FileCheck::Kind::Outside);
    CHECK(check.reason.find("--allow-read DIR") != std::string::npos);
    ReadPermissions allowed;
    allowed.allowRead.push_back((tree.base / "outside").string());
    FileAccess wider(allowed);
    wider.addRoot(tree.base / "root");
    CHECK(wider.check(tree.base / "root" / "link.crt").readable());
}

TEST_CASE("folders and FIFOs are refused with their reason, even when all is allowed", "[access]") {
    Tree tree;
    REQUIRE(::mkfifo((tree.base / "root" / "pipe").c_str(), 0600) == 0);
    ReadPermissions all;
    all.allowAll = true;
    FileAccess access(all);
    CHECK(access.check(tree.base / "outside" / "secret.crt").readable());
    CHECK(access.check(tree.base / "root" / "sub").reason == "is a folder, not a file");
    CHECK(access.check(tree.base / "root" / "pipe").reason == "is a FIFO (named pipe), not a file");
    CHECK(access.check("/dev/null").reason == "is a device, not a file");
}

TEST_CASE("a script's roots: its folder, the include path and the asset roots", "[access]") {
    Tree tree;
    IncludeSearch includes;
    includes.dirs.push_back((tree.base / "outside").string());
    FileAccess access = scriptFileAccess(tree.base / "root", includes, {}, {});
    CHECK(access.check(tree.base / "root" / "inside.crt").readable());
    CHECK(access.check(tree.base / "outside" / "secret.crt").readable());
    CHECK(access.check("/etc/passwd").refused());
    const FoundInclude found = includes.find("../outside/secret.crt", tree.base / "root", access);
    CHECK(found.path == tree.base / "root" / "../outside/secret.crt");
    const FoundInclude refused = includes.find("/etc/passwd", tree.base / "root", access);
    CHECK(refused.path.empty());
    CHECK(refused.refusal.starts_with("is outside the folders a script may read"));
}
