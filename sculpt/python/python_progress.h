// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file python_progress.h
/// @brief Long work called from Python: run without the GIL (other Python threads go on), with a
///        progress callback that hands the fraction to the caller's function (returning False
///        cancels) and honours Ctrl-C: the KeyboardInterrupt, or the caller's own exception,
///        is raised in Python once the work has stopped.

#include "core/base/progress.h"

#include <pybind11/pybind11.h>

#include <optional>

namespace sculpt::python {

class PythonProgress {
public:
    /// `callback`: None, or a function taking the fraction done in [0, 1].
    explicit PythonProgress(pybind11::object callback) : mCallback(std::move(callback)) {}

    /// Runs `work(progress)` with the GIL released; a stop asked for by Ctrl-C or by the
    /// callback (its exception, or its False) is raised in Python.
    template <typename Work>
    auto run(const Work& work)
    {
        try {
            pybind11::gil_scoped_release release;
            return work(callback());
        } catch (const Cancelled&) {
            if (mError) throw *mError;
            throw;
        }
    }

private:
    Progress callback();

    pybind11::object mCallback;
    std::optional<pybind11::error_already_set> mError;  // set with the GIL held
};

}  // namespace sculpt::python
