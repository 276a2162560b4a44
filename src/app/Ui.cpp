#include "app/Ui.h"

#include "platform/GlfwWindow.h"

#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace gi::app {
namespace {

constexpr ImGuiWindowFlags kPanel = ImGuiWindowFlags_AlwaysAutoResize |
        ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
        ImGuiWindowFlags_NoNav;

std::string formatBytes(std::size_t bytes) {
    char text[32];
    if (bytes >= (std::size_t(1) << 20)) {
        std::snprintf(text, sizeof text, "%.2f MiB", double(bytes) / double(1 << 20));
    } else if (bytes >= 1024) {
        std::snprintf(text, sizeof text, "%.1f KiB", double(bytes) / 1024.0);
    } else {
        std::snprintf(text, sizeof text, "%zu B", bytes);
    }
    return text;
}

void passTable(const std::vector<gl::PassTiming>& timings) {
    constexpr ImGuiTableFlags kFlags =
            ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_SizingFixedFit;
    if (!ImGui::BeginTable("passes", 3, kFlags)) return;
    ImGui::TableSetupColumn("pass");
    ImGui::TableSetupColumn("GPU ms");
    ImGui::TableSetupColumn("CPU ms");
    ImGui::TableHeadersRow();
    for (const gl::PassTiming& pass : timings) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(pass.name.c_str());
        ImGui::TableNextColumn();
        if (pass.samples > 0) ImGui::Text("%8.3f", pass.gpuMsAverage);
        else ImGui::TextDisabled("%8s", "...");
        ImGui::TableNextColumn();
        ImGui::Text("%8.3f", pass.cpuMsAverage);
    }
    ImGui::EndTable();
}

void memoryTable(const std::vector<gl::MemoryItem>& memory) {
    std::size_t total = 0;
    for (const gl::MemoryItem& item : memory) total += item.bytes;
    // Closed at first: the total is in the header, the table would cover half the scene.
    if (!ImGui::TreeNodeEx("memory", ImGuiTreeNodeFlags_None, "GPU memory  %s",
                formatBytes(total).c_str())) {
        return;
    }
    if (ImGui::BeginTable("memory items", 2, ImGuiTableFlags_SizingFixedFit)) {
        for (const gl::MemoryItem& item : memory) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(item.name.c_str());
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(formatBytes(item.bytes).c_str());
        }
        ImGui::EndTable();
    }
    ImGui::TreePop();
}

// "render 640x360 (50%, moving)   budget 100 ms": what the frame budget chose.
void resolutionLine(const UiFrame& frame) {
    char budget[32];
    if (frame.budgetMs > 0.0f) {
        std::snprintf(budget, sizeof budget, "budget %.0f ms", double(frame.budgetMs));
    } else {
        std::snprintf(budget, sizeof budget, "budget off");
    }
    char size[48];
    if (frame.reduced && frame.framebufferSize.x > 0) {
        std::snprintf(size, sizeof size, "%ld%%, moving",
                std::lround(100.0 * frame.renderSize.x / frame.framebufferSize.x));
    } else {
        std::snprintf(size, sizeof size, "full");
    }
    ImGui::Text("render %dx%d (%s)   %s", frame.renderSize.x, frame.renderSize.y, size, budget);
}

// Widgets for a few Settings; ranges are those Settings.cpp accepts for the same keys.
bool settingsWidgets(Settings& settings) {
    bool changed = false;
    static const char* const kModels[] = {"phong", "gltf"};
    changed |= ImGui::Combo("material.model", &settings.materialModel, kModels, 2);
    changed |= ImGui::SliderFloat("material.specular", &settings.specular, 0.0f, 1.0f, "%.3f",
            ImGuiSliderFlags_AlwaysClamp);
    changed |= ImGui::SliderFloat("material.shininess", &settings.shininess, 1.0f, 4096.0f,
            "%.1f", ImGuiSliderFlags_AlwaysClamp | ImGuiSliderFlags_Logarithmic);
    // Read every frame by the viewer; no renderer setting changes with it.
    ImGui::SliderFloat("view.frame_budget_ms", &settings.frameBudgetMs, 0.0f, 1000.0f, "%.0f",
            ImGuiSliderFlags_AlwaysClamp);
    return changed;
}

} // namespace

Ui::~Ui() {
    if (!mInitialised) return;
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
}

bool Ui::init(platform::GlfwWindow& window, std::string& error) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;   // never write imgui.ini into the user's directory
    ImGui::StyleColorsDark();
    ImGui::GetStyle().WindowRounding = 4.0f;
    if (!ImGui_ImplGlfw_InitForOpenGL(window.handle(), true)) {
        ImGui::DestroyContext();
        error = "the ImGui GLFW backend failed to initialise";
        return false;
    }
    if (!ImGui_ImplOpenGL3_Init("#version 450")) {
        ImGui_ImplGlfw_Shutdown();
        ImGui::DestroyContext();
        error = "the ImGui OpenGL3 backend failed to initialise (its loader could not open libGL)";
        return false;
    }
    mInitialised = true;
    return true;
}

bool Ui::wantsMouse() const { return mInitialised && ImGui::GetIO().WantCaptureMouse; }

bool Ui::wantsKeyboard() const { return mInitialised && ImGui::GetIO().WantTextInput; }

void Ui::helpWindow() {
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(display.x - 8.0f, 8.0f), ImGuiCond_Always,
            ImVec2(1.0f, 0.0f));
    ImGui::SetNextWindowBgAlpha(0.8f);
    if (ImGui::Begin("hotkeys", &mShowHelp, kPanel)) {
        if (ImGui::BeginTable("hotkeys", 2, ImGuiTableFlags_SizingFixedFit)) {
            for (const HotkeyHelp& line : mHotkeys) {
                ImGui::TableNextRow();
                ImGui::TableNextColumn();
                ImGui::TextUnformatted(line.keys.c_str());
                ImGui::TableNextColumn();
                ImGui::TextUnformatted(line.action.c_str());
            }
            ImGui::EndTable();
        }
    }
    ImGui::End();
}

bool Ui::draw(const UiFrame& frame, Settings& settings, gl::GpuProfiler& profiler) {
    if (!mInitialised) return false;
    mFrameMs[std::size_t(mHistoryNext)] = float(frame.frameMs);
    mHistoryNext = (mHistoryNext + 1) % kHistory;

    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();

    ImGui::SetNextWindowPos(ImVec2(8.0f, 8.0f), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowBgAlpha(0.8f);
    bool changed = false;
    if (ImGui::Begin("voxatlas", nullptr, kPanel)) {
        ImGui::Text("mode %s   output %s   %dx%d   vsync %s", frame.mode.c_str(),
                frame.output.c_str(), frame.framebufferSize.x, frame.framebufferSize.y,
                frame.vsync ? "on" : "off");
        ImGui::Text("exposure %s", frame.exposure.c_str());
        resolutionLine(frame);
        if (!frame.giStatus.empty()) ImGui::TextUnformatted(frame.giStatus.c_str());
        if (!frame.shadowStatus.empty()) ImGui::TextUnformatted(frame.shadowStatus.c_str());
        const double fps = frame.frameMs > 0.0 ? 1000.0 / frame.frameMs : 0.0;
        char overlay[64];
        std::snprintf(overlay, sizeof overlay, "%.2f ms  %.1f fps", frame.frameMs, fps);
        const float peak = *std::max_element(mFrameMs.begin(), mFrameMs.end());
        ImGui::PlotLines("##frame", mFrameMs.data(), kHistory, mHistoryNext, overlay, 0.0f,
                std::max(peak * 1.1f, 1.0f), ImVec2(300.0f, 48.0f));
        ImGui::Text("triangles %zu   camera %s   speed %.2f m/s", frame.triangles,
                frame.camera.c_str(), double(frame.speed));
        ImGui::Separator();
        passTable(frame.timings);
        ImGui::Separator();
        memoryTable(frame.memory);
        if (!frame.plan.empty() && ImGui::CollapsingHeader("resource plan")) {
            ImGui::TextUnformatted(frame.plan.c_str());
        }
        ImGui::Separator();
        changed = settingsWidgets(settings);
        if (!frame.notice.empty()) {
            ImGui::Separator();
            ImGui::TextColored(ImVec4(1.0f, 0.85f, 0.3f, 1.0f), "%s", frame.notice.c_str());
        }
        if (!frame.openError.empty()) {
            ImGui::Separator();
            ImGui::TextColored(ImVec4(1.0f, 0.4f, 0.4f, 1.0f), "%s", frame.openError.c_str());
        }
        if (!frame.shaderErrors.empty()) {
            ImGui::Separator();
            ImGui::TextColored(ImVec4(1.0f, 0.4f, 0.4f, 1.0f), "shader reload failed:");
            ImGui::PushTextWrapPos(ImGui::GetFontSize() * 50.0f);
            ImGui::TextUnformatted(frame.shaderErrors.c_str());
            ImGui::PopTextWrapPos();
        }
        ImGui::Separator();
        ImGui::TextDisabled("H: %s hotkey help", mShowHelp ? "hide" : "show");
    }
    ImGui::End();

    if (mShowHelp) helpWindow();

    ImGui::Render();
    {
        gl::GpuScope scope(profiler, "ui/overlay");
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glDisable(GL_FRAMEBUFFER_SRGB);
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    }
    return changed;
}

} // namespace gi::app
