# CPack: `cpack` in the build folder (or `bash packaging/setup.sh package`) builds
# raystudio_<version>_amd64.deb from the install rules. Included from the top-level
# CMakeLists.txt after every install rule is known.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME raystudio)
set(CPACK_PACKAGE_VENDOR "RayStudio maintainers")
set(CPACK_PACKAGE_CONTACT "RayStudio maintainers <maintainers@users.noreply.h-seed-b04c9f78.example>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "interactive ray-traced 3D scene designer")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
# Stripped binaries, and directories 0755 whatever the builder's umask.
set(CPACK_STRIP_FILES ON)
set(CPACK_INSTALL_DEFAULT_DIRECTORY_PERMISSIONS
  OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ GROUP_EXECUTE WORLD_READ WORLD_EXECUTE)

set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
# The run-time libraries (Qt 6, oneTBB, OpenImageIO, assimp, Embree) come from dpkg-shlibdeps.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# Loaded as a Qt plugin, so dpkg-shlibdeps cannot see it: the toolbar's SVG icons need it.
set(CPACK_DEBIAN_PACKAGE_DEPENDS "libqt6svg6")
set(CPACK_DEBIAN_PACKAGE_GENERATE_SHLIBS OFF)
# The extended description only: CPack puts the summary above it as the synopsis.
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION
  "RayStudio is a desktop scene designer whose viewport is a CPU Whitted ray
tracer: place spheres, planes, boxes, rectangles and meshes, give them
diffuse, Phong, mirror and glass materials, add point and sphere lights,
and the ray-traced image follows every click and drag.
.
The package also contains raystudio-cli, which renders, validates and
benchmarks the same scene files from the command line, and example scenes.")

include(CPack)
