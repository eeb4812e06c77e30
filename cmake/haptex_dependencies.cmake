# The libraries haptex's modules link, found the same way by haptex's own build and by a project that
# uses an installed haptex (haptexConfig.cmake includes this file from lib/cmake/haptex). The
# pkg-config names of the same libraries, for haptex.pc, are HAPTEX_PC_REQUIRES.
find_package(PkgConfig REQUIRED)
pkg_check_modules(FFTW3 REQUIRED IMPORTED_TARGET fftw3 fftw3f)
pkg_check_modules(PUGIXML REQUIRED IMPORTED_TARGET pugixml)
pkg_check_modules(HDF5 REQUIRED IMPORTED_TARGET hdf5)
pkg_check_modules(LIBUSB REQUIRED IMPORTED_TARGET libusb-1.0)
pkg_check_modules(SNDFILE REQUIRED IMPORTED_TARGET sndfile)
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
# Eigen's fast math takes float square roots from rsqrtps plus a Newton step; rsqrtps's last bits are
# the CPU maker's own. Adam divides by such a root every step, so training took another path on another
# CPU and `make demo`'s figures (docs/benchmark.md) were the machine's. sqrtps is exact on every x86-64.
set_property(TARGET Eigen3::Eigen APPEND PROPERTY INTERFACE_COMPILE_DEFINITIONS EIGEN_FAST_MATH=0)
find_package(nlohmann_json 3 REQUIRED)
find_package(Threads REQUIRED)
find_package(OpenCV 4 REQUIRED COMPONENTS core imgproc imgcodecs videoio)
find_package(Boost 1.74 REQUIRED)
find_package(ZLIB REQUIRED)
find_package(ALSA REQUIRED)  # play/: a sound card (libasound2-dev)
find_package(JPEG REQUIRED)  # dataset/decode_image.cpp: libjpeg itself, to keep its warnings off stderr
set(HAPTEX_PC_REQUIRES "fftw3 fftw3f pugixml hdf5 libusb-1.0 sndfile eigen3 nlohmann_json opencv4 zlib alsa libjpeg")
