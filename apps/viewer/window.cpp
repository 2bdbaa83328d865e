#include "viewer/window.hpp"

#include "viewer/renderer/gl.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <cstring>
#include <stdexcept>
#include <string>
#include <utility>

namespace tumble::viewer {
namespace {

std::string lastGlfwError()
{
    const char* description = nullptr;
    glfwGetError(&description);
    return description ? description : "unknown GLFW error";
}

} // namespace

Window::Window(const WindowOptions& options)
{
    if (glfwInit() != GLFW_TRUE) {
        throw std::runtime_error("cannot start GLFW (no display? run under xvfb-run): " +
                                 lastGlfwError());
    }
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_VISIBLE, options.visible ? GLFW_TRUE : GLFW_FALSE);
    glfwWindowHint(GLFW_SAMPLES, options.visible ? 4 : 0);
    m_window = glfwCreateWindow(options.width, options.height, options.title, nullptr, nullptr);
    if (m_window == nullptr) {
        const std::string error = lastGlfwError();
        glfwTerminate();
        throw std::runtime_error("cannot open an OpenGL 3.3 core window: " + error);
    }
    glfwMakeContextCurrent(m_window);
    glfwSwapInterval(1);
    // multisampling costs a software renderer (Mesa's llvmpipe) more than it is worth
    const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    if (renderer != nullptr && (std::strstr(renderer, "llvmpipe") || std::strstr(renderer, "softpipe"))) {
        glDisable(GL_MULTISAMPLE);
    }

    // our key callback first: ImGui's backend chains to the callback it finds installed
    glfwSetWindowUserPointer(m_window, this);
    glfwSetKeyCallback(m_window, &Window::onKey);

    // ImGui: no imgui.ini written next to the user's files
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;
    ImGui::StyleColorsDark();
    ImGui::GetStyle().WindowRounding = 4.0f;
    ImGui_ImplGlfw_InitForOpenGL(m_window, true);
    ImGui_ImplOpenGL3_Init("#version 330 core");
}

Window::~Window()
{
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    glfwDestroyWindow(m_window);
    glfwTerminate();
}

bool Window::shouldClose() const { return glfwWindowShouldClose(m_window) == GLFW_TRUE; }

void Window::pollEvents() const { glfwPollEvents(); }

double Window::time() const { return glfwGetTime(); }

glm::ivec2 Window::framebufferSize() const
{
    glm::ivec2 size(0);
    glfwGetFramebufferSize(m_window, &size.x, &size.y);
    return size;
}

void Window::beginUiFrame(std::optional<glm::ivec2> displaySize) const
{
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    if (displaySize) {
        ImGuiIO& io = ImGui::GetIO();
        io.DisplaySize = ImVec2(static_cast<float>(displaySize->x), static_cast<float>(displaySize->y));
        io.DisplayFramebufferScale = ImVec2(1.0f, 1.0f);
    }
    ImGui::NewFrame();
}

void Window::renderUi() const
{
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

void Window::swapBuffers() const { glfwSwapBuffers(m_window); }

std::vector<KeyPress> Window::takeKeyPresses() { return std::exchange(m_keyPresses, {}); }

void Window::onKey(GLFWwindow* window, int key, int /*scancode*/, int action, int /*mods*/)
{
    auto* self = static_cast<Window*>(glfwGetWindowUserPointer(window));
    if (self != nullptr && (action == GLFW_PRESS || action == GLFW_REPEAT)) {
        self->m_keyPresses.push_back({.key = key, .repeat = action == GLFW_REPEAT});
    }
}

} // namespace tumble::viewer
