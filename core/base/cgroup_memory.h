// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file cgroup_memory.h
/// @brief The memory a control group still allows this process: the limit a batch scheduler
///        (Slurm's --mem), a container (docker --memory) or systemd sets, which /proc/meminfo
///        does not show. Past it the kernel kills the job with no message (exit 137).

#include <cstdint>
#include <optional>
#include <string>

namespace sculpt {

/// The least, over the process's control group and every group above it, of its memory limit
/// minus its working set (usage less inactive file cache, which the kernel reclaims first), for
/// cgroup v2 and the v1 memory controller; nullopt when no group sets a limit. The groups are
/// found once per process, their limits and usage read at each call.
std::optional<std::uint64_t> cgroupMemoryLeft();

/// The same, from the text of /proc/self/cgroup and /proc/self/mountinfo (whose mount points
/// say where the groups' files are).
std::optional<std::uint64_t> cgroupMemoryLeft(const std::string& procCgroup, const std::string& mountinfo);

}  // namespace sculpt
