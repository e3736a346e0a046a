# Builds creatures/*.json into the binary: generated/shipped_creatures_data.cpp
# defines bx::shipped_creatures() (genome/shipped_creatures.h), so a stage's
# `file` names a canonical creature from any folder. The text is kept byte for
# byte: a stage's file_hash is its hash.
include(${CMAKE_CURRENT_LIST_DIR}/embed_files.cmake)
embed_files(CREATURES_CPP ${CMAKE_SOURCE_DIR}/creatures json genome/shipped_creatures.h ShippedCreature shipped_creatures bxcreature)
