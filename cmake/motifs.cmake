# Builds motifs/*.json into the binary: generated/shipped_motifs_data.cpp
# defines bx::shipped_motifs() (eval/motif_file.h), so a config's motif.file
# names a shipped motif from any folder. The text is kept byte for byte:
# motif.hash is its hash.
include(${CMAKE_CURRENT_LIST_DIR}/embed_files.cmake)
embed_files(MOTIFS_CPP ${CMAKE_SOURCE_DIR}/motifs json eval/motif_file.h ShippedMotif shipped_motifs bxmotif)
