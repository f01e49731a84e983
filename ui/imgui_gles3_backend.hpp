#pragma once

// Dear ImGui's OpenGL3 renderer backend (Debian's imgui_impl_opengl3.cpp), compiled for GLES 3
// under these names by ui/CMakeLists.txt so it cannot clash with the desktop-GL copy inside
// Debian's libimgui.a.
struct ImDrawData;

bool steerseg_ImGui_ImplGles3_Init(const char* glslVersion);
void steerseg_ImGui_ImplGles3_Shutdown();
void steerseg_ImGui_ImplGles3_NewFrame();
void steerseg_ImGui_ImplGles3_RenderDrawData(ImDrawData* drawData);
