# IdleSearchLimitTest derives a strategy from Explorer, which nxtmap_common builds without RTTI (brick style):
# that file is built the same way, so the derived class needs no typeinfo of its base.
set_source_files_properties(${dir}/IdleSearchLimitTest.cpp PROPERTIES COMPILE_OPTIONS -fno-rtti)
