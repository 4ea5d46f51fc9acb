# A run killed while writing (#61) leaves "<file>.tmp.PID.N" temporaries behind; after
# `psxrl train --resume` the run folder must hold its documented files only (docs/agents.md).
# PID 4194305 is past Linux's largest PID (PID_MAX_LIMIT, 4194304): no such process can run.
# Arguments: -DPSXRL=<psxrl executable> -DRUN=<run folder to use>.
file(REMOVE_RECURSE ${RUN})
set(train ${PSXRL} train --agent q --test-every 2 --max-moves 2 --seed 3 --quiet --out ${RUN})
execute_process(COMMAND ${train} --episodes 2 RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "the first run failed (${code}): ${out}${err}")
endif()
file(WRITE ${RUN}/learning_curve.png.tmp.4194305.0 "half a picture")
file(WRITE ${RUN}/checkpoint.psxrl.tmp.4194305.3 "half a checkpoint")
execute_process(COMMAND ${train} --episodes 3 --resume RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "the resumed run failed (${code}): ${out}${err}")
endif()
file(GLOB left RELATIVE ${RUN} ${RUN}/*)
list(SORT left)
set(documented checkpoint.psxrl config.json learning_curve.png metrics.csv metrics.jsonl)
if(NOT left STREQUAL documented)
  message(FATAL_ERROR "the run folder holds [${left}], expected [${documented}]")
endif()
message("the run folder holds its documented files only: ${left}")
