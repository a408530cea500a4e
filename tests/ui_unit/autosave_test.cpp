// SPDX-License-Identifier: Apache-2.0
// Autosave without a window: when it writes (changed, interval passed, never mid-stroke), where,
// and that the copies are the user's alone whatever the umask.

#include "core/field/grid_checksum.h"
#include "core/io/vdb_file.h"
#include "sculpt/session/document.h"
#include "tests/support/temp_dir.h"
#include "ui/document/autosave.h"

#include <sys/stat.h>

#include <gtest/gtest.h>

namespace sculpt::ui {
namespace {

namespace fs = std::filesystem;
using test::TempDir;

mode_t modeOf(const fs::path& path)
{
    struct stat s {};
    EXPECT_EQ(stat(path.c_str(), &s), 0) << path;
    return s.st_mode & 07777;
}

Document smallBall() { return Document::create(NewShape{NewShape::Kind::Sphere, 6.0, 0.5}); }

/// An edit: the ball becomes a larger one, one undo step.
void grow(Document& document)
{
    document.replaceField(Document::create(NewShape{NewShape::Kind::Sphere, 7.0, 0.5}).session().field().deepCopy(),
                          "grow");
}

TEST(Autosave, WritesOnlyChangedWorkOncePerIntervalAndNeverMidStroke)
{
    TempDir dir;
    Autosave autosave(dir / "state", 10.0);
    Document document = smallBall();
    std::string error;
    EXPECT_FALSE(autosave.tick(document, 100.0, false, error)) << "nothing to save yet";
    grow(document);
    EXPECT_FALSE(autosave.tick(document, 100.0, true, error)) << "a stroke is under way";
    EXPECT_TRUE(autosave.tick(document, 100.0, false, error));
    const fs::path copy = autosave.recoveryFile(document.path());
    EXPECT_EQ(gridChecksum(readFieldImage(copy).grid()), gridChecksum(document.session().field().grid()));
    grow(document);
    EXPECT_FALSE(autosave.tick(document, 105.0, false, error)) << "within the interval";
    EXPECT_TRUE(autosave.tick(document, 111.0, false, error));
    EXPECT_FALSE(autosave.tick(document, 200.0, false, error)) << "unchanged since the last copy";
    EXPECT_FALSE(autosave.save(document, error)) << "unchanged since the last copy";
    EXPECT_TRUE(error.empty()) << error;
}

TEST(Autosave, CopiesAreOwnerOnlyWhateverTheUmaskAndAreOfferedUntilDiscarded)
{
    TempDir dir;
    const mode_t saved = umask(0);
    Autosave autosave(dir / "state", 120.0);
    Document document = smallBall();
    grow(document);
    std::string error;
    ASSERT_TRUE(autosave.save(document, error)) << error;  // before a read: no interval to wait
    umask(saved);
    const fs::path copy = autosave.recoveryFile(document.path());
    EXPECT_EQ(modeOf(dir / "state"), 0700u);
    EXPECT_EQ(modeOf(dir / "state" / "recovery"), 0700u);
    EXPECT_EQ(modeOf(copy), 0600u);
    EXPECT_EQ(TempDir::entriesOf(dir / "state" / "recovery").size(), 1u) << "no temporary left behind";
    EXPECT_EQ(autosave.pending(document.path()), copy);
    autosave.discard(document.path());
    EXPECT_FALSE(autosave.pending(document.path()));
}

TEST(Autosave, EachDocumentHasItsOwnCopy)
{
    TempDir dir;
    const Autosave autosave(dir / "state", 120.0);
    EXPECT_NE(autosave.recoveryFile(dir / "a" / "face.vdb"), autosave.recoveryFile(dir / "b" / "face.vdb"));
    EXPECT_NE(autosave.recoveryFile(""), autosave.recoveryFile(dir / "face.vdb"));
    EXPECT_EQ(autosave.recoveryFile(dir / "face.vdb").parent_path(), dir / "state" / "recovery");
}

}  // namespace
}  // namespace sculpt::ui
