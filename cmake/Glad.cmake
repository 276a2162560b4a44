# Generates the glad 2 GL 4.5 core loader at configure time from Debian's python3-glad.
# The loader takes a GetProcAddress function, so one build serves GLFW, EGL and OSMesa.
find_program(GLAD_EXECUTABLE glad REQUIRED)
set(GLAD_OUT "${CMAKE_BINARY_DIR}/glad")
set(GLAD_EXTENSIONS GL_KHR_debug,GL_ARB_bindless_texture)
if(NOT EXISTS "${GLAD_OUT}/src/gl.c")
    message(STATUS "Generating glad GL 4.5 core loader")
    execute_process(
        COMMAND ${GLAD_EXECUTABLE} --quiet --reproducible --api gl:core=4.5
                --extensions ${GLAD_EXTENSIONS} --out-path ${GLAD_OUT} c
        RESULT_VARIABLE GLAD_RESULT OUTPUT_QUIET ERROR_VARIABLE GLAD_ERROR)
    if(NOT GLAD_RESULT EQUAL 0)
        message(FATAL_ERROR "glad generation failed: ${GLAD_ERROR}")
    endif()
endif()
add_library(voxatlas_glad STATIC "${GLAD_OUT}/src/gl.c")
target_include_directories(voxatlas_glad SYSTEM PUBLIC "${GLAD_OUT}/include")
set_target_properties(voxatlas_glad PROPERTIES POSITION_INDEPENDENT_CODE ON)
