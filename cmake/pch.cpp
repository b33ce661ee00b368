// The translation unit that builds the studies' precompiled headers (CMakeLists.txt geomint_study_pch).
