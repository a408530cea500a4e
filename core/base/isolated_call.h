// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file isolated_call.h
/// @brief Runs a third-party decoder in a forked child process under an address-space and CPU
///        limit, so that its abort, crash, runaway allocation or endless loop ends the child
///        and becomes one InputError in the caller, whose document and window live on.
///
/// Why a child and not checks in front of the library: GDCM asserts and VTK's readers crash on
/// damage deep inside codecs (JPEG 2000, JPEG-LS, RLE) that no header check reaches, and a
/// limit on one process is the only bound on what a library allocates. Why fork and not a
/// helper program: the readers live in core/, which then needs no executable to be found.
/// The child runs only the decoder: it must use no thread pool (the parent's worker threads do
/// not exist in it) and it leaves with _exit, so none of the parent's atexit work runs twice.
/// Its stdout and stderr go to /dev/null: a library's chatter never reaches the user's terminal.

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <memory>
#include <string>

namespace sculpt {

/// What a child may use and how its failure is named.
struct IsolationLimits {
    std::string subject;            ///< the file or directory read, for messages
    std::string reader;             ///< "the DICOM reader", for messages
    std::uint64_t memoryBytes = 0;  ///< address space the child may add to what it inherits
    int cpuSeconds = 300;           ///< processor time; the wall clock allows twice that and 30 s
};

/// What the child hands back: a short header and a body of any size. The body is malloc'ed,
/// so that a VTK array can adopt it without a copy.
struct IsolatedBytes {
    std::string header;
    std::unique_ptr<char, void (*)(void*)> body{nullptr, std::free};
    std::size_t bodyBytes = 0;
};

/// The child's view of what it sends back (the body is only read, never copied).
struct ChildReply {
    std::string header;
    const void* body = nullptr;
    std::size_t bodyBytes = 0;
    std::shared_ptr<const void> owner = nullptr;  ///< keeps the body alive until it is sent
};

/// Whether runIsolated forks (the default) or runs `work` in this process. A fuzzer turns it
/// off: it must see a decoder's crash in its own process, where a child would turn it into a
/// refusal (and its fork under libFuzzer's threads can deadlock).
void setIsolation(bool enabled);

/// Runs `work` in a child process and returns its reply. An InputError the child throws is
/// thrown here with its message; a crash, signal or limit becomes an InputError naming
/// `limits.subject` (or the file the child last named with noteIsolatedSubject) and the reader.
/// `work` may hold references to the caller's data: the child has a copy of all of it.
IsolatedBytes runIsolated(const IsolationLimits& limits, const std::function<ChildReply()>& work);

/// Inside runIsolated's child: the file being decoded now, named if the child dies on it.
/// Does nothing outside a child.
void noteIsolatedSubject(const std::string& subject);

}  // namespace sculpt
