// Window: the GLFW window with its OpenGL 3.3 core context, and the Dear ImGui context with the
// GLFW and OpenGL3 backends. Made and torn down together, in the right order.
#pragma once

#include <glm/glm.hpp>

#include <optional>
#include <vector>

struct GLFWwindow;

namespace tumble::viewer {

/// A key going down (or repeating while held), as GLFW names it.
struct KeyPress {
    int key = 0;
    bool repeat = false;
};

struct WindowOptions {
    int width = 1280;
    int height = 720;
    /// False for the capture mode: the window only carries the GL context.
    bool visible = true;
    const char* title = "tumble view";
};

class Window {
public:
    /// Throws std::runtime_error when GLFW, the window or the GL 3.3 core context fails (no
    /// display: run under xvfb-run).
    explicit Window(const WindowOptions& options);
    ~Window();
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    [[nodiscard]] bool shouldClose() const;
    void pollEvents() const;
    /// Seconds since GLFW started.
    [[nodiscard]] double time() const;
    /// Size of the drawable area, pixels.
    [[nodiscard]] glm::ivec2 framebufferSize() const;

    /// Starts an ImGui frame; `displaySize` replaces the window's size (capture draws the UI
    /// into an offscreen target of its own size).
    void beginUiFrame(std::optional<glm::ivec2> displaySize = std::nullopt) const;
    /// Ends the ImGui frame and draws it into the bound framebuffer.
    void renderUi() const;
    void swapBuffers() const;
    /// The key presses since the last call, in order. Kept as events: a tap shorter than a
    /// frame still counts (ImGui 1.86 only sees which keys are down at each frame).
    [[nodiscard]] std::vector<KeyPress> takeKeyPresses();

private:
    static void onKey(GLFWwindow* window, int key, int scancode, int action, int mods);

    GLFWwindow* m_window = nullptr;
    std::vector<KeyPress> m_keyPresses;
};

} // namespace tumble::viewer
