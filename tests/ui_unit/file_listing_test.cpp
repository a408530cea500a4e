// SPDX-License-Identifier: Apache-2.0
// The file chooser's listing and Tab completion, on a real directory: folders first, only the
// kinds a prompt accepts, hidden files left out, a bounded listing, completion to the longest
// shared prefix.

#include "tests/support/temp_dir.h"
#include "ui/document/file_listing.h"

#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

using namespace sculpt::ui;
using sculpt::test::TempDir;

namespace {

void write(const std::filesystem::path& path, std::size_t bytes)
{
    std::ofstream(path, std::ios::binary) << std::string(bytes, 'x');
}

std::vector<std::string> names(const DirectoryListing& listing)
{
    std::vector<std::string> out;
    for (const FileEntry& e : listing.entries) out.push_back(e.folder ? e.name + "/" : e.name);
    return out;
}

}  // namespace

TEST(FileListing, ShowsFoldersFirstThenTheAcceptedFilesWithTheirSizes)
{
    TempDir dir;
    std::filesystem::create_directory(dir / "series");
    std::filesystem::create_directory(dir / "b");
    write(dir / "ball.vdb", 1234);
    write(dir / "HEAD.VDB", 10);
    write(dir / "notes.txt", 5);
    write(dir / ".hidden.vdb", 5);
    write(dir / "brain.nii.gz", 7);
    write(dir / "slice0001", 9);

    const DirectoryListing documents = listDirectory(dir.path(), {{".vdb"}});
    EXPECT_EQ(names(documents), (std::vector<std::string>{"b/", "series/", "HEAD.VDB", "ball.vdb"}));
    EXPECT_EQ(documents.entries[3].bytes, 1234u);
    EXPECT_GT(documents.entries[3].modified, 0);
    EXPECT_FALSE(documents.truncated);
    EXPECT_TRUE(documents.error.empty());

    const FileKinds scans{{".nii.gz", ".nrrd"}, true, true};  // DICOM slices often have no extension
    EXPECT_EQ(names(listDirectory(dir.path(), scans)),
              (std::vector<std::string>{"b/", "series/", "brain.nii.gz", "slice0001"}));
    EXPECT_FALSE(listDirectory(dir / "missing", scans).error.empty());
}

TEST(FileListing, AHugeFolderIsListedOnlyUpToItsLimit)
{
    TempDir dir;
    for (int i = 0; i < 50; ++i) write(dir / ("f" + std::to_string(i) + ".vdb"), 1);
    const DirectoryListing listing = listDirectory(dir.path(), {{".vdb"}}, 10);
    EXPECT_EQ(listing.entries.size(), 10u);
    EXPECT_TRUE(listing.truncated);
}

TEST(FileListing, TabCompletesToTheLongestSharedPrefixAndALoneFolderGetsItsSlash)
{
    TempDir dir;
    std::filesystem::create_directory(dir / "brains");
    write(dir / "brain.nii.gz", 1);
    write(dir / "ball.vdb", 1);
    write(dir / "bald.vdb", 1);
    const std::string root = dir.path().string() + "/";
    const FileKinds documents{{".vdb"}};
    EXPECT_EQ(completePath(root + "bal", documents), root + "bal");        // ball and bald share "bal"
    EXPECT_EQ(completePath(root + "bale", documents), root + "bale");      // nothing starts so
    EXPECT_EQ(completePath(root + "ball", documents), root + "ball.vdb");  // one file
    EXPECT_EQ(completePath(root + "br", documents), root + "brains/");     // the .nii.gz is not listed
    EXPECT_EQ(completePath(root + "br", {{".nii.gz"}}), root + "brain");   // brain.nii.gz and brains/
    EXPECT_EQ(directoryOf(root + "ball.vdb"), dir.path());
    EXPECT_EQ(directoryOf(root + "brains"), dir / "brains");
    EXPECT_EQ(directoryOf("name.vdb"), std::filesystem::path());
}
