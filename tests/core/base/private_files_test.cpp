// SPDX-License-Identifier: Apache-2.0
#include "core/base/atomic_file.h"
#include "core/base/private_directory.h"
#include "tests/support/temp_dir.h"

#include <sys/stat.h>

#include <gtest/gtest.h>

#include <fstream>

namespace sculpt {
namespace {

namespace fs = std::filesystem;
using test::TempDir;

mode_t modeOf(const fs::path& path)
{
    struct stat s {};
    EXPECT_EQ(stat(path.c_str(), &s), 0) << path;
    return s.st_mode & 07777;
}

/// Runs with the widest umask, as a careless login shell might have it.
class PrivateFiles : public ::testing::Test {
protected:
    void SetUp() override { mSaved = umask(0); }
    void TearDown() override { umask(mSaved); }

private:
    mode_t mSaved = 0;
};

TEST_F(PrivateFiles, AStateDirectoryAndItsMissingParentsAreMadeOwnerOnly)
{
    TempDir dir;
    const fs::path state = dir / "home" / ".local" / "state" / "sculpt";
    makePrivateDirectory(state / "recovery");
    for (const fs::path& made : {dir / "home", dir / "home" / ".local", state, state / "recovery"})
        EXPECT_EQ(modeOf(made), 0700u) << made;

    const fs::path old = dir / "old-state";
    fs::create_directory(old);
    fs::permissions(old, fs::perms::all);
    makePrivateDirectory(old);
    EXPECT_EQ(modeOf(old), 0700u);
}

TEST_F(PrivateFiles, FilesWrittenIntoAPrivateDirectoryAreOwnerOnlyAndSoAreTheirTemporaries)
{
    TempDir dir;
    makePrivateDirectory(dir / "state");
    const fs::path recent = dir / "state" / "recent.json";
    {
        AtomicFile file(recent);
        EXPECT_EQ(modeOf(file.temporaryPath()), 0600u);
        std::ofstream(file.temporaryPath()) << "[]\n";
        EXPECT_EQ(modeOf(file.temporaryPath()), 0600u);
        file.commit();
    }
    EXPECT_EQ(modeOf(recent), 0600u);
    // A file an older version left readable becomes private when it is next written.
    fs::permissions(recent, fs::perms::all);
    writeFileAtomically(recent, "[\"a\"]\n");
    EXPECT_EQ(modeOf(recent), 0600u);
}

TEST_F(PrivateFiles, ReplacingAFileKeepsItsPermissions)
{
    TempDir dir;
    const fs::path shared = dir / "shared";
    fs::create_directory(shared);
    fs::permissions(shared, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                                fs::perms::others_read | fs::perms::others_exec);
    const fs::path document = shared / "patient.vdb";
    std::ofstream(document) << "old";
    fs::permissions(document, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read,
                    fs::perm_options::replace);
    writeFileAtomically(document, "new");
    EXPECT_EQ(modeOf(document), 0640u);
    // A new file outside a private directory follows the umask (here 0: 0666).
    writeFileAtomically(shared / "new.vdb", "new");
    EXPECT_EQ(modeOf(shared / "new.vdb"), 0666u);
}

}  // namespace
}  // namespace sculpt
