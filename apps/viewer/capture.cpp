#include "viewer/capture.hpp"

#include "viewer/renderer/gl.hpp"
#include "viewer/renderer/offscreen_target.hpp"

#include <stb_image_write.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <stdexcept>
#include <vector>

namespace tumble::viewer {
namespace {

/// Multisampling of the capture target: none (0; GL may round 1 up to a multisampled buffer).
/// Multisampling would smooth the silhouettes but doubles the frame time under Mesa's software
/// renderer, where captures are made.
constexpr int kCaptureSamples = 0;

/// Processor time used so far by every thread of the process, ms.
double processCpuMs()
{
    timespec now{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
    return 1e3 * static_cast<double>(now.tv_sec) + 1e-6 * static_cast<double>(now.tv_nsec);
}

double timedFrame(const OffscreenTarget& target, const std::function<void()>& drawFrame)
{
    const auto start = std::chrono::steady_clock::now();
    target.bind();
    drawFrame();
    glFinish();
    const std::chrono::duration<double, std::milli> elapsed =
        std::chrono::steady_clock::now() - start;
    return elapsed.count();
}

/// Appends stb's encoded bytes to a std::vector<std::uint8_t>.
void appendBytes(void* context, void* data, int size)
{
    auto* bytes = static_cast<std::vector<std::uint8_t>*>(context);
    const auto* first = static_cast<const std::uint8_t*>(data);
    bytes->insert(bytes->end(), first, first + size);
}

} // namespace

CaptureTiming captureFrame(const std::function<void(std::span<const std::uint8_t>)>& write,
                           int width, int height, const std::function<void()>& drawFrame)
{
    const OffscreenTarget target(width, height, kCaptureSamples);
    CaptureTiming timing;
    timing.renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    timing.firstFrameMs = timedFrame(target, drawFrame);

    std::vector<double> frames;
    const double cpuStart = processCpuMs();
    for (int i = 0; i < kTimedCaptureFrames; ++i) {
        frames.push_back(timedFrame(target, drawFrame));
    }
    timing.cpuFrameMs = (processCpuMs() - cpuStart) / kTimedCaptureFrames;
    std::sort(frames.begin(), frames.end());
    timing.medianFrameMs = frames[frames.size() / 2];
    timing.timedFrames = kTimedCaptureFrames;

    const std::vector<std::uint8_t> pixels = target.readRgb();
    std::vector<std::uint8_t> png;
    if (stbi_write_png_to_func(appendBytes, &png, width, height, 3, pixels.data(), width * 3) ==
        0) {
        throw std::runtime_error("cannot encode the frame as PNG");
    }
    write(png);
    return timing;
}

} // namespace tumble::viewer
