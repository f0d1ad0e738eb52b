# Every dependency is a Debian package (see tools/debian-packages.txt); nothing is
# downloaded at build time.

find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(tinyxml2 REQUIRED)
find_package(assimp REQUIRED)
find_package(fmt REQUIRED)
find_package(spdlog REQUIRED)
find_package(PNG REQUIRED)  # height-map textures (engine/scene_compiler/grey_png.cpp)
find_package(CLI11 REQUIRED)
find_package(Threads REQUIRED)

# Bullet: MHD uses Debian's double-precision build (libBullet*-float64), so btScalar is
# double everywhere, the same precision as our own geometry.
find_path(MHD_BULLET_INCLUDE_DIR btBulletCollisionCommon.h PATH_SUFFIXES bullet REQUIRED)
find_library(MHD_BULLET_COLLISION_LIB BulletCollision-float64 REQUIRED)
find_library(MHD_BULLET_LINEARMATH_LIB LinearMath-float64 REQUIRED)
find_library(MHD_BULLET_DYNAMICS_LIB BulletDynamics-float64 REQUIRED)
add_library(mhd_bullet INTERFACE)
target_include_directories(mhd_bullet SYSTEM INTERFACE "${MHD_BULLET_INCLUDE_DIR}")
target_compile_definitions(mhd_bullet INTERFACE BT_USE_DOUBLE_PRECISION)
# BulletDynamics: rigid bodies of pushable objects (engine/dynamics); before the
# collision library it uses.
target_link_libraries(mhd_bullet INTERFACE ${MHD_BULLET_DYNAMICS_LIB} ${MHD_BULLET_COLLISION_LIB} ${MHD_BULLET_LINEARMATH_LIB})
add_library(mhd::bullet ALIAS mhd_bullet)

# xxHash (content keys of the BVH cache); Debian ships no CMake config for it.
find_path(MHD_XXHASH_INCLUDE_DIR xxhash.h REQUIRED)
find_library(MHD_XXHASH_LIB xxhash REQUIRED)
add_library(mhd_xxhash INTERFACE)
target_include_directories(mhd_xxhash SYSTEM INTERFACE "${MHD_XXHASH_INCLUDE_DIR}")
target_link_libraries(mhd_xxhash INTERFACE ${MHD_XXHASH_LIB})
add_library(mhd::xxhash ALIAS mhd_xxhash)
