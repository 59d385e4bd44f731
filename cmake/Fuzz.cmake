# PPR_FUZZ=ON (the `fuzz` preset): every target is compiled with AddressSanitizer, UndefinedBehavior-
# Sanitizer and libFuzzer's coverage instrumentation, and only tests/fuzz's targets (plus the
# libraries they link) are built by default. libFuzzer ships with clang only; Debian's clang-14 and
# libclang-rt-14-dev come from scripts/install-deps.sh.
if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  message(FATAL_ERROR "PPR_FUZZ needs clang with libFuzzer (cmake --preset fuzz uses clang++-14); got ${CMAKE_CXX_COMPILER_ID}")
endif()

# Any UB aborts (no recovery), so libFuzzer records it as a crash with its input.
set(PPR_SANITIZE -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer)
add_compile_options(${PPR_SANITIZE} -fsanitize=fuzzer-no-link)
add_link_options(-fsanitize=address,undefined)

# ppr_add_fuzzer(NAME name SOURCES a.cpp LINK libs...): a libFuzzer executable in <build>/bin.
function(ppr_add_fuzzer)
  cmake_parse_arguments(ARG "" "NAME" "SOURCES;LINK" ${ARGN})
  add_executable(${ARG_NAME} ${ARG_SOURCES})
  target_link_libraries(${ARG_NAME} PRIVATE ${ARG_LINK})
  target_link_options(${ARG_NAME} PRIVATE -fsanitize=fuzzer)
  set_target_properties(${ARG_NAME} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/bin)
endfunction()
