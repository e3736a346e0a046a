# Builds presets/*.toml into the binary: generated/presets_data.cpp defines
# bx::presets() (io/presets.h).
include(${CMAKE_CURRENT_LIST_DIR}/embed_files.cmake)
embed_files(PRESETS_CPP ${CMAKE_SOURCE_DIR}/presets toml io/presets.h Preset presets bxpreset)
