# The libraries geomint builds on (Debian packages: scripts/install-deps.sh): found by this tree's
# CMakeLists.txt and by the build tree's geomint-config.cmake (a project of experiments outside it).
find_package(Eigen3 3.3 REQUIRED NO_MODULE)
find_package(Boost 1.74 REQUIRED)                 # header-only: odeint
find_package(tomlplusplus REQUIRED)
find_package(CLI11 REQUIRED)
find_package(nlohmann_json 3.10 REQUIRED)
find_package(OpenMP REQUIRED COMPONENTS CXX)
