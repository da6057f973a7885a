# emit(1), the command's manual page, made from its own help by help2man: the top-level --help,
# then one section per command with that command's --help (the list read from the top-level help),
# compressed as Debian wants it (gzip -9n). Run at build time by CMakeLists.txt:
#   cmake -DEMIT=<the built emit> -DHELP2MAN=<help2man> -DGZIP=<gzip> -DOUTPUT=<emit.1.gz> -P man_page.cmake
execute_process(COMMAND ${EMIT} --help OUTPUT_VARIABLE help COMMAND_ERROR_IS_FATAL ANY)
string(REGEX REPLACE ".*\nSubcommands:\n" "" commands "${help}")
string(REGEX MATCHALL "(^|\n)  [a-z]+ " commands "${commands}")
get_filename_component(folder ${OUTPUT} DIRECTORY)
set(include_file ${folder}/emit.h2m)
file(WRITE ${include_file} "[COMMANDS]\nEach command's options, as `emit COMMAND --help` prints them.\n")
foreach(command IN LISTS commands)
  string(STRIP "${command}" command)
  execute_process(COMMAND ${EMIT} ${command} --help OUTPUT_VARIABLE command_help COMMAND_ERROR_IS_FATAL ANY)
  # roff: a backslash starts an escape, and a line starting with a dot or a quote is a request.
  string(REPLACE "\\" "\\e" command_help "${command_help}")
  string(REGEX REPLACE "(^|\n)([.'])" "\\1\\\\&\\2" command_help "${command_help}")
  file(APPEND ${include_file} ".SS \"emit ${command}\"\n.nf\n${command_help}.fi\n")
endforeach()
file(APPEND ${include_file} "[SEE ALSO]\n/usr/share/doc/emit/README.md: the sensor description, the methods, the figures.\n")
execute_process(COMMAND ${HELP2MAN} --no-info --no-discard-stderr --include ${include_file}
                        --name "pressure images from tomographic tactile sensors" ${EMIT}
                OUTPUT_FILE ${folder}/emit.1 COMMAND_ERROR_IS_FATAL ANY)
execute_process(COMMAND ${GZIP} -9nf ${folder}/emit.1 COMMAND_ERROR_IS_FATAL ANY)
