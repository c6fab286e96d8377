# The player of an exported reproducer (harness/export/export_c.h): its files
# in the order tools/embed_player.cmake joins them into the one C file the
# export writes. Each file holds one step; a later one uses what the earlier
# ones define (C: no prototypes, every function static).
set(RAYSPEC_PLAYER_PARTS
    case_data_types.c          # the types of the case's data, and the marker it is spliced at
    instance_and_device.c      # the instance, the device picked and created, its functions
    buffers_and_commands.c     # host-visible buffers with addresses, command submission
    images.c                   # the storage images (outputs.images): made, cleared, copied back
    acceleration_structures.c  # a level's structures: created, built, updated
    structure_copies.c         # their copies: cloned, compacted, serialized and back
    structure_queries.c        # their properties queried (scene.build.queries), checked
    scene_builds.c             # the bottom levels, then the top levels over them
    pipeline.c                 # the ray tracing pipeline (or raygen's compute pipeline) from the SPIR-V
    shader_binding_table.c     # the SBT written with the device's group handles
    descriptors.c              # the descriptor set: the top level and the buffers
    comparison.c               # the records and counters against the expectations, printed
    image_comparison.c         # the images against the model's, within the tolerances
    trace_and_readback.c)      # main: every step in order, the trace or dispatch, the verdict
