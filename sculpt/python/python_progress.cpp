// SPDX-License-Identifier: Apache-2.0
#include "sculpt/python/python_progress.h"

namespace sculpt::python {

namespace py = pybind11;

Progress PythonProgress::callback()
{
    return [this](double fraction) {
        py::gil_scoped_acquire acquire;
        if (mError) return false;
        if (PyErr_CheckSignals() != 0) {  // Ctrl-C (on the main thread): KeyboardInterrupt pending
            mError.emplace();
            return false;
        }
        if (mCallback.is_none()) return true;
        try {
            const py::object answer = mCallback(fraction);
            return answer.is_none() || answer.cast<bool>();
        } catch (py::error_already_set& e) {
            mError.emplace(std::move(e));
            return false;
        }
    };
}

}  // namespace sculpt::python
