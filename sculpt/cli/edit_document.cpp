#include "sculpt/cli/edit_document.h"

#include "core/base/atomic_file.h"
#include "core/base/errors.h"
#include "core/io/vdb_file.h"
#include "sculpt/cli/progress_bar.h"
#include "sculpt/session/model_filter.h"

namespace sculpt::cli {

FieldImage editDocument(const std::string& input, const std::string& output, const std::string& label,
                        const std::function<void(FieldImage&, const Progress&)>& edit)
{
    AtomicFile::checkTarget(output);
    FieldImage field = readFieldImage(input);
    {
        ProgressBar bar(label);
        edit(field, bar.callback());
    }
    refuseEmptyResult(field, input, label);
    writeFieldImage(field, output);
    return field;
}

}  // namespace sculpt::cli
