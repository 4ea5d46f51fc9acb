# Robustness (#61): broken integrations, runaway scripts, corrupt level states and stale
# temporary files, as a user meets them through psxrl train. Included from tests/CMakeLists.txt
# (uses its psxrl_cli_test, BAD and RUNS). Each integration is Tumble's, changed in one way,
# written at configure time under ${BAD}/games (PSXRL_GAMES points there).
set(ROBUST_GAMES ${BAD}/games)
file(READ ${PROJECT_SOURCE_DIR}/games/tumble/game.toml tumble_toml)
# Tumble's manifest under another name, with its program and maps found by absolute path.
function(robust_game name extra_top script)
  string(REPLACE "name = \"tumble\"" "name = \"${name}\"\n${extra_top}" m "${tumble_toml}")
  string(REPLACE "exe = \"tumble.exe\"" "exe = \"${PROJECT_BINARY_DIR}/games/tumble/tumble.exe\"" m "${m}")
  string(REPLACE "maps = \"levels/" "maps = \"${PROJECT_SOURCE_DIR}/games/tumble/levels/" m "${m}")
  file(MAKE_DIRECTORY ${ROBUST_GAMES}/${name})
  file(WRITE ${ROBUST_GAMES}/${name}/game.toml "${m}")
  file(WRITE ${ROBUST_GAMES}/${name}/game.lua "${script}")
endfunction()
function(robust_train_test name code output)
  psxrl_cli_test(${name} ${code} "${output}" ${ARGN})
  set_tests_properties(cli.${name} PROPERTIES ENVIRONMENT PSXRL_GAMES=${ROBUST_GAMES})
endfunction()

# The issue's script: 1e5 strings of 1e5 bytes in on_reset, stopped at 4 MiB at its line (4).
robust_game(memhog "script_memory_mib = 4"
            "-- allocates without end when a level starts\nfunction on_reset(level, seed)\n  local t = {}\n  for i = 1, 1e5 do t[i] = string.rep('y', 1e5) .. i end\nend\n")
robust_train_test(train_script_memory_limit 2 "game.lua:4: memory limit (4 MiB) exceeded (in on_reset())"
                  train --game memhog --agent q --episodes 1 --quiet --out ${RUNS}/memhog)
# A manifest whose name is not its folder's.
robust_game(misnamed "" "")
file(READ ${ROBUST_GAMES}/misnamed/game.toml m)
string(REPLACE "name = \"misnamed\"" "name = \"tumble\"" m "${m}")
file(WRITE ${ROBUST_GAMES}/misnamed/game.toml "${m}")
robust_train_test(train_misnamed_game 2 "game.toml:4: name: 'tumble' differs from the folder's name 'misnamed'"
                  train --game misnamed --agent q --episodes 1 --quiet --out ${RUNS}/misnamed)
# A program that is nowhere: the manifest's line and both folders searched.
robust_game(noexe "" "")
file(READ ${ROBUST_GAMES}/noexe/game.toml m)
string(REPLACE "exe = \"${PROJECT_BINARY_DIR}/games/tumble/tumble.exe\"" "exe = \"gone.exe\"" m "${m}")
file(WRITE ${ROBUST_GAMES}/noexe/game.toml "${m}")
robust_train_test(train_missing_program 2
                  "noexe/game.toml:10: [boot] exe: 'gone.exe' is in neither ${ROBUST_GAMES}/noexe/ nor ${PROJECT_BINARY_DIR}/games/noexe/"
                  train --game noexe --agent q --episodes 1 --quiet --out ${RUNS}/noexe)
# Levels from save states, the state corrupt: bad input (2), and no claim of an intact checkpoint.
robust_game(corrupt "" "")
file(READ ${ROBUST_GAMES}/corrupt/game.toml m)
string(REPLACE "start = \"request\"" "start = \"state\"\nstate = \"{folder}/level{level:02}.state\"" m "${m}")
string(REPLACE "request_variable = \"request_level\"\n" "" m "${m}")
file(WRITE ${ROBUST_GAMES}/corrupt/game.toml "${m}")
file(WRITE ${ROBUST_GAMES}/corrupt/level01.state "PSXRL but not a save state")
add_test(NAME cli.train_corrupt_level_state
  COMMAND ${CMAKE_COMMAND} -DEXPECT_CODE=2 "-DEXPECT_OUTPUT=no checkpoint was written yet" "-DEXPECT_NO_OUTPUT=is intact"
          "-DCOMMAND=$<TARGET_FILE:psxrl>|train|--game|corrupt|--agent|q|--episodes|1|--quiet|--out|${RUNS}/corrupt"
          -P ${CMAKE_CURRENT_SOURCE_DIR}/expect.cmake)
set_tests_properties(cli.train_corrupt_level_state PROPERTIES ENVIRONMENT PSXRL_GAMES=${ROBUST_GAMES})
robust_train_test(train_corrupt_level_state_names_it 2 "corrupt/level01.state: "
                  train --game corrupt --agent q --episodes 1 --quiet --out ${RUNS}/corrupt2)
# A run killed while writing left temporaries of a dead process; --resume removes them and leaves
# only the run folder's documented files (docs/agents.md).
add_test(NAME cli.train_resume_leaves_documented_files
  COMMAND ${CMAKE_COMMAND} -DPSXRL=$<TARGET_FILE:psxrl> -DRUN=${RUNS}/litter
          -P ${CMAKE_CURRENT_SOURCE_DIR}/run_folder_clean.cmake)
