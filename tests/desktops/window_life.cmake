# Window life (docs/reliability.md): minimise and restore, then 100 resizes in a row, under Xvfb
# with a window manager (jwm), --validation on, resident memory checked (tests/desktops/window_life.sh).
find_program(JWM jwm)
find_program(XDOTOOL xdotool)
if(XVFB_RUN AND JWM AND XDOTOOL)
    foreach(number 06 10 14 15)
        chapter_test(window-life.chapter-${number}
            COMMAND ${XVFB_RUN} -a -s "-screen 0 1600x1200x24" ${CMAKE_CURRENT_SOURCE_DIR}/desktops/window_life.sh
                    $<TARGET_FILE:chapter-${number}> --device llvmpipe --validation --width 640 --height 360
            EXPECT_STDOUT "minimised: [0-9]+ frames ended.*resident memory slope over 100 resizes: -?[0-9]+ kB per resize" QUIET_STDERR)
    endforeach()
else()
    message(WARNING "Xvfb, jwm or xdotool not found: the window-life tests are not registered")
endif()
