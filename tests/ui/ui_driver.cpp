// SPDX-License-Identifier: Apache-2.0
#include "tests/ui/ui_driver.h"

#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <vtkImageData.h>
#include <vtkPNGReader.h>

#include <cstdlib>
#include <fstream>
#include <signal.h>
#include <sstream>
#include <stdexcept>

namespace sculpt::test {

std::string uiCommand(const std::string& args)
{
    // xvfb-run -a looks for a free display from a start number: start each run elsewhere, so
    // tests running side by side (ctest -j) do not race for the same one.
    static int runs = 0;
    const int start = 100 + int(getpid() % 400) * 8 + (runs++ % 8);
    return "xvfb-run -a -n " + std::to_string(start) + " -s '-screen 0 1280x800x24' '" SCULPT_UI_EXECUTABLE "' " + args;
}

BackgroundUi::BackgroundUi(const std::string& args, const std::filesystem::path& workDir)
{
    const std::string command = "cd '" + workDir.string() + "' && exec " + uiCommand(args) + " >/dev/null 2>&1";
    const pid_t child = fork();
    if (child == 0) {
        setpgid(0, 0);
        execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
        _exit(127);
    }
    setpgid(child, child);  // as the child does: whichever runs first
    mGroup = int(child);
}

BackgroundUi::~BackgroundUi()
{
    if (mGroup <= 0) return;
    kill(-mGroup, SIGKILL);
    waitpid(mGroup, nullptr, 0);
}

bool BackgroundUi::killProgram()
{
    // The group's members from /proc: "PID (COMM) STATE PPID PGRP ...".
    for (const auto& entry : std::filesystem::directory_iterator("/proc")) {
        std::ifstream stat(entry.path() / "stat");
        std::string line;
        if (!std::getline(stat, line)) continue;
        const std::size_t close = line.rfind(')');
        if (close == std::string::npos || line.find("(sculpt-ui)") == std::string::npos) continue;
        std::istringstream rest(line.substr(close + 2));
        char state = 0;
        int parent = 0, group = 0;
        rest >> state >> parent >> group;
        if (group != mGroup) continue;
        return kill(pid_t(std::stoi(entry.path().filename().string())), SIGKILL) == 0;
    }
    return false;
}

CommandResult runUi(const std::string& args, const std::string& workDir)
{
    CommandResult result;
    for (int attempt = 0; attempt < 3; ++attempt) {
        result = runCommand(uiCommand(args), workDir);
        if (result.err.find("xvfb-run: error") == std::string::npos) break;  // the X server, not the program
    }
    return result;
}

vtkSmartPointer<vtkImageData> readPng(const std::filesystem::path& path)
{
    vtkNew<vtkPNGReader> reader;
    reader->SetFileName(path.c_str());
    reader->Update();
    vtkSmartPointer<vtkImageData> image = reader->GetOutput();
    return image;
}

double differingShare(vtkImageData* a, vtkImageData* b)
{
    const int* da = a->GetDimensions();
    const int* db = b->GetDimensions();
    if (da[0] != db[0] || da[1] != db[1]) return 1.0;
    const auto* pa = static_cast<const unsigned char*>(a->GetScalarPointer());
    const auto* pb = static_cast<const unsigned char*>(b->GetScalarPointer());
    const int channels = a->GetNumberOfScalarComponents();
    std::size_t differ = 0, pixels = std::size_t(da[0]) * std::size_t(da[1]);
    for (std::size_t p = 0; p < pixels; ++p) {
        for (int c = 0; c < 3; ++c) {
            if (std::abs(int(pa[p * channels + c]) - int(pb[p * channels + c])) > 8) {
                ++differ;
                break;
            }
        }
    }
    return double(differ) / double(pixels);
}

}  // namespace sculpt::test
