# A text file compiled in: cmake -DINPUT=file -DOUTPUT=file.cpp -DNAME=ns::symbol -P embed_text.cmake
# writes OUTPUT defining `extern const char* const symbol` in namespace ns (a raw string
# literal of the file's text); OUTPUT is left as it is when its text would not change.
file(READ "${INPUT}" text)
set(delimiter "tackle_embedded")
if(text MATCHES "\\)${delimiter}\"")
  message(FATAL_ERROR "${INPUT} holds the raw string's end, )${delimiter}\"")
endif()
string(REGEX REPLACE "::[^:]*$" "" namespace "${NAME}")
string(REGEX REPLACE "^.*::" "" symbol "${NAME}")
file(WRITE "${OUTPUT}.new"
     "// Generated from ${INPUT} by cmake/embed_text.cmake: do not edit.\n"
     "namespace ${namespace} {\nextern const char* const ${symbol};\n"
     "const char* const ${symbol} = R\"${delimiter}(${text})${delimiter}\";\n}\n")
file(COPY_FILE "${OUTPUT}.new" "${OUTPUT}" ONLY_IF_DIFFERENT)
file(REMOVE "${OUTPUT}.new")
