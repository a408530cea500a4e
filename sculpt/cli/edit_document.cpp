// SPDX-License-Identifier: Apache-2.0
#include "sculpt/cli/edit_document.h"

#include "core/base/atomic_file.h"
#include "core/base/errors.h"
#include "sculpt/cli/progress_bar.h"
#include "sculpt/session/model_filter.h"

namespace sculpt::cli {

FieldImage editDocument(const DocumentInput& input, const std::string& output, const std::string& label,
                        const std::function<void(FieldImage&, const Progress&)>& edit)
{
    AtomicFile::checkTarget(output);
    VdbDocument document = readDocument(input);
    FieldImage& field = document.field;
    {
        ProgressBar bar(label);
        edit(field, bar.callback());
    }
    refuseEmptyResult(field, input.path, label);
    writeFieldImage(field, output, document.companions);
    return field;
}

}  // namespace sculpt::cli
