# The documentation (tests/docs/check_docs.py, label docs; docs/testing.md): links and anchors of README.md, docs/ and
# reports/README.md, every docs page reachable from the README and in mkdocs.yml's nav, the site built by MkDocs with
# --strict (skipped without mkdocs), and the README's commands run as written (first deck, user UMAT, picture) with
# their results against the closed forms it quotes; every option of an `ldfcz ...` command line in the docs exists.
set(_docs_check "${CMAKE_CURRENT_SOURCE_DIR}/docs/check_docs.py")
add_test(NAME docs_links COMMAND Python3::Interpreter ${_docs_check} links "${PROJECT_SOURCE_DIR}")
add_test(NAME docs_options COMMAND Python3::Interpreter ${_docs_check} options "${PROJECT_SOURCE_DIR}"
  --exe $<TARGET_FILE:ldfcz>)
add_test(NAME docs_mkdocs COMMAND Python3::Interpreter ${_docs_check} mkdocs "${PROJECT_SOURCE_DIR}"
  --out ${LDFCZ_RUNS}/docs_site)
add_test(NAME docs_readme_commands COMMAND Python3::Interpreter ${_docs_check} commands "${PROJECT_SOURCE_DIR}"
  --exe $<TARGET_FILE:ldfcz> --out ${LDFCZ_RUNS}/docs_readme_commands)
set_tests_properties(docs_links docs_options docs_mkdocs docs_readme_commands PROPERTIES LABELS "docs" TIMEOUT 120
  PASS_REGULAR_EXPRESSION "PASS" FAIL_REGULAR_EXPRESSION "FAIL")
set_tests_properties(docs_mkdocs PROPERTIES SKIP_RETURN_CODE 77)
