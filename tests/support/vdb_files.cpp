// SPDX-License-Identifier: Apache-2.0
#include "tests/support/vdb_files.h"

#include <openvdb/io/File.h>

namespace sculpt::test {

void writeNamedGrids(const std::filesystem::path& path, const std::vector<std::pair<std::string, FieldImage>>& grids,
                     const openvdb::MetaMap& meta)
{
    openvdb::initialize();
    openvdb::GridCPtrVec out;
    for (const auto& [name, field] : grids) {
        auto grid = field.grid().deepCopy();
        grid->setName(name);
        out.push_back(grid);
    }
    openvdb::io::File(path.string()).write(out, meta);
}

}  // namespace sculpt::test
