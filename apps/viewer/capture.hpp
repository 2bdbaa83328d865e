// The capture mode: draw a frame into an offscreen target of a given size, time it, and encode
// it as a PNG file.
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <string>

namespace tumble::viewer {

struct CaptureTiming {
    /// The first frame, including shader compilation and first-use costs, ms.
    double firstFrameMs = 0.0;
    /// Median of the timed frames after it, ms (wall clock).
    double medianFrameMs = 0.0;
    /// Processor time the process spent per timed frame, ms, all threads (the software
    /// renderer's included): the cost of a frame, whatever else the machine is doing.
    double cpuFrameMs = 0.0;
    int timedFrames = 0;
    /// GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)".
    std::string renderer;
};

/// Frames drawn and timed after the first one.
inline constexpr int kTimedCaptureFrames = 10;

/// Calls `drawFrame` (which draws into the bound framebuffer, width x height) into an offscreen
/// target once, then kTimedCaptureFrames more times, each finished with glFinish and timed, and
/// hands the last frame, encoded as a whole PNG file, to `write`, which stores it or throws.
CaptureTiming captureFrame(const std::function<void(std::span<const std::uint8_t>)>& write,
                           int width, int height, const std::function<void()>& drawFrame);

} // namespace tumble::viewer
