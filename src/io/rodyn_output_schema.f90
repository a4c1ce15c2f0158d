!> The one description of rodyn's output: every column of every CSV table, with its
!> unit and a one-line meaning, in the order written, and every HDF5 dataset with its
!> units and description. The table writer (rodyn_output_table, used by rodyn_output and
!> rodyn_output_dynamic) lays out the line tables' rows from these columns, and takes
!> the header rows and the datasets' `units` and `description` attributes from here; the
!> Python readers their columns and the units they expect (postproc/rodyn_post/schema.py,
!> written from this file by tools/gen_output_schema.py); docs/output.md lists the same
!> tables, columns and datasets with the same units. tests/program/check_output_schema.py
!> checks all of them against this table (read through output_schema_dump.f90).
!>
!> A row of `output_columns` is 'file | column | unit | meaning'; the unit '-' means
!> none (a name, a count, a ratio).
module rodyn_output_schema
   implicit none
   private
   public :: output_columns, output_datasets, schema_field, schema_header, schema_tables
   public :: schema_dataset, status_keys, environment_datasets, schema_environment
   public :: output_attributes, row_len

   integer, parameter :: row_len = 240  !< longest row of the tables

   !> Every column of every CSV table, file by file, in the order written: the static
   !> tables', then the dynamic tables' (two arrays: a statement has at most 255 lines).
   character(len=row_len), parameter :: static_columns(*) = [character(len=row_len) :: &
      'static_nodes.csv | line | - | line name', &
      'static_nodes.csv | node | - | node number along the line, from 1 (end A)', &
      'static_nodes.csv | s_m | m | unstretched arc length S of the node', &
      'static_nodes.csv | x_m | m | x of the node, global axes', &
      'static_nodes.csv | y_m | m | y of the node, global axes', &
      'static_nodes.csv | z_m | m | z of the node, global axes', &
      'static_nodes.csv | seabed_normal_N_per_m | N/m | seabed normal contact force per length', &
      'static_nodes.csv | seabed_friction_N_per_m | N/m | seabed friction force per length', &
      'static_elements.csv | line | - | line name', &
      'static_elements.csv | element | - | element number along the line, from 1 at end A', &
      'static_elements.csv | point | - | integration point within the element, from 1', &
      'static_elements.csv | s_m | m | unstretched arc length S of the point', &
      'static_elements.csv | effective_tension_N | N | N3, along d3, positive in tension', &
      'static_elements.csv | wall_tension_N | N | wall (true) tension', &
      'static_elements.csv | shear_1_N | N | N1, along d1', &
      'static_elements.csv | shear_2_N | N | N2, along d2', &
      'static_elements.csv | moment_1_Nm | N m | M1, bending moment about d1', &
      'static_elements.csv | moment_2_Nm | N m | M2, bending moment about d2', &
      'static_elements.csv | torque_Nm | N m | M3, torsional moment about d3', &
      'static_elements.csv | curvature_1_per_m | 1/m | K1, bending curvature about d1', &
      'static_elements.csv | curvature_2_per_m | 1/m | K2, bending curvature about d2', &
      'static_elements.csv | twist_per_m | 1/m | K3, twist', &
      'static_elements.csv | curvature_per_m | 1/m | total bending curvature', &
      'static_reactions.csv | line | - | line name', &
      'static_reactions.csv | end | - | A (S = 0) or B (S = L)', &
      'static_reactions.csv | Fx_N | N | x force of the support on the line', &
      'static_reactions.csv | Fy_N | N | y force of the support on the line', &
      'static_reactions.csv | Fz_N | N | z force of the support on the line', &
      'static_reactions.csv | Mx_Nm | N m | x moment of the support on the line', &
      'static_reactions.csv | My_Nm | N m | y moment of the support on the line', &
      'static_reactions.csv | Mz_Nm | N m | z moment of the support on the line', &
      'static_reactions.csv | tension_N | N | magnitude of the support force', &
      'static_points.csv | point | - | point name (*POINT)', &
      'static_points.csv | type | - | FIXED or FREE', &
      'static_points.csv | x_m | m | x of the point, global axes', &
      'static_points.csv | y_m | m | y of the point, global axes', &
      'static_points.csv | z_m | m | z of the point, global axes', &
      'static_points.csv | Fx_N | N | x force of the lines on the point', &
      'static_points.csv | Fy_N | N | y force of the lines on the point', &
      'static_points.csv | Fz_N | N | z force of the lines on the point', &
      'static_points.csv | lines | - | line ends on the point', &
      'static_stiffness.csv | row_object | - | FREE point or body of the force (row)', &
      'static_stiffness.csv | row_dof | - | x, y, z (force) or rx, ry, rz (moment about R)', &
      'static_stiffness.csv | column_object | - | FREE point or body moved (column)', &
      'static_stiffness.csv | column_dof | - | x, y, z (a move) or rx, ry, rz (a turn)', &
      'static_stiffness.csv | stiffness | - | K = -dF/dq of everything, in the unit column', &
      'static_stiffness.csv | lines_stiffness | - | K of the lines alone, in the unit column', &
      'static_stiffness.csv | unit | - | N/m, N/rad, N m/m or N m/rad', &
      'static_bodies.csv | body | - | body name (*BODY)', &
      'static_bodies.csv | type | - | FIXED or FREE', &
      'static_bodies.csv | x_m | m | x of the reference point R, global axes', &
      'static_bodies.csv | y_m | m | y of R, global axes', &
      'static_bodies.csv | z_m | m | z of R, global axes', &
      'static_bodies.csv | rx_rad | rad | rotation vector from the start, x', &
      'static_bodies.csv | ry_rad | rad | rotation vector from the start, y', &
      'static_bodies.csv | rz_rad | rad | rotation vector from the start, z', &
      'static_bodies.csv | Fx_N | N | x force of the lines on the body', &
      'static_bodies.csv | Fy_N | N | y force of the lines on the body', &
      'static_bodies.csv | Fz_N | N | z force of the lines on the body', &
      'static_bodies.csv | Mx_Nm | N m | x moment of the lines about R', &
      'static_bodies.csv | My_Nm | N m | y moment of the lines about R', &
      'static_bodies.csv | Mz_Nm | N m | z moment of the lines about R', &
      'static_body_modes.csv | body | - | body name (*BODY, FREE)', &
      'static_body_modes.csv | mode | - | mode number, by period (longest first)', &
      'static_body_modes.csv | period_s | s | natural period (0: no restoring)', &
      'static_body_modes.csv | x | - | mode shape: x of R (largest entry 1)', &
      'static_body_modes.csv | y | - | mode shape: y of R', &
      'static_body_modes.csv | z | - | mode shape: z of R', &
      'static_body_modes.csv | rx | - | mode shape: rotation about x [rad per unit]', &
      'static_body_modes.csv | ry | - | mode shape: rotation about y', &
      'static_body_modes.csv | rz | - | mode shape: rotation about z', &
      'static_offset_curve.csv | body | - | body name (*OFFSET CURVE)', &
      'static_offset_curve.csv | step | - | step of the force, 0 for the equilibrium', &
      'static_offset_curve.csv | force_N | N | horizontal force at R towards HEADING', &
      'static_offset_curve.csv | offset_m | m | move of R along the force from step 0', &
      'static_offset_curve.csv | x_m | m | x of R, global axes', &
      'static_offset_curve.csv | y_m | m | y of R, global axes', &
      'static_offset_curve.csv | z_m | m | z of R, global axes', &
      'static_offset_curve.csv | rx_rad | rad | rotation vector from the start, x', &
      'static_offset_curve.csv | ry_rad | rad | rotation vector from the start, y', &
      'static_offset_curve.csv | rz_rad | rad | rotation vector from the start, z', &
      'static_offset_curve.csv | max_end_force_N | N | largest force on a line end on the body', &
      'static_modes.csv | mode | - | mode number, longest period first (*MODAL)', &
      'static_modes.csv | period_s | s | natural period about the static equilibrium', &
      'static_modes.csv | frequency_hz | Hz | natural frequency', &
      'static_modes.csv | dominant | - | line, point or body with the largest share of '// &
         'the kinetic energy', &
      'static_modes.csv | share | - | that share of the kinetic energy (0 to 1)', &
      'static_mode_shapes.csv | mode | - | mode number (static_modes.csv)', &
      'static_mode_shapes.csv | object | - | line name, or FREE point or body name', &
      'static_mode_shapes.csv | node | - | node number along the line from 1 (end A); 0 '// &
         'a point or body', &
      'static_mode_shapes.csv | s_m | m | unstretched arc length S of the node (0 a point '// &
         'or body)', &
      'static_mode_shapes.csv | x | - | x translation [m; largest translation of the '// &
         'system 1 m] (a body: of its R)', &
      'static_mode_shapes.csv | y | - | y translation [m]', &
      'static_mode_shapes.csv | z | - | z translation [m]', &
      'static_mode_shapes.csv | rx | - | rotation about x [rad] (0 without rotation unknowns)', &
      'static_mode_shapes.csv | ry | - | rotation about y [rad]', &
      'static_mode_shapes.csv | rz | - | rotation about z [rad]', &
      'static_lines.csv | line | - | line name', &
      'static_lines.csv | length_m | m | unstretched length L', &
      'static_lines.csv | touchdown_s_m | m | largest S in contact with the seabed (between '// &
         'the last node in contact and the next); -1 when none', &
      'environment.csv | key | - | name of the quantity', &
      'environment.csv | value | - | its value, in the unit of the row', &
      'environment.csv | unit | - | unit of the value']
   character(len=row_len), parameter :: dynamic_columns(*) = [character(len=row_len) :: &
      'dynamic_nodes.csv | time_s | s | time of the frame', &
      'dynamic_nodes.csv | line | - | line name', &
      'dynamic_nodes.csv | node | - | node number along the line, from 1 (end A)', &
      'dynamic_nodes.csv | s_m | m | unstretched arc length S of the node', &
      'dynamic_nodes.csv | x_m | m | x of the node, global axes', &
      'dynamic_nodes.csv | y_m | m | y of the node, global axes', &
      'dynamic_nodes.csv | z_m | m | z of the node, global axes', &
      'dynamic_nodes.csv | seabed_normal_N_per_m | N/m | seabed normal contact force per length', &
      'dynamic_nodes.csv | seabed_friction_N_per_m | N/m | seabed friction force per length', &
      'dynamic_elements.csv | time_s | s | time of the frame', &
      'dynamic_elements.csv | line | - | line name', &
      'dynamic_elements.csv | element | - | element number along the line, from 1 at end A', &
      'dynamic_elements.csv | point | - | integration point within the element, from 1', &
      'dynamic_elements.csv | s_m | m | unstretched arc length S of the point', &
      'dynamic_elements.csv | effective_tension_N | N | N3, along d3, positive in tension', &
      'dynamic_elements.csv | wall_tension_N | N | wall (true) tension', &
      'dynamic_elements.csv | moment_1_Nm | N m | M1, bending moment about d1', &
      'dynamic_elements.csv | moment_2_Nm | N m | M2, bending moment about d2', &
      'dynamic_elements.csv | torque_Nm | N m | M3, torsional moment about d3', &
      'dynamic_elements.csv | curvature_per_m | 1/m | total bending curvature', &
      'dynamic_lines.csv | time_s | s | time of the frame', &
      'dynamic_lines.csv | line | - | line name', &
      'dynamic_lines.csv | touchdown_s_m | m | largest S in contact with the seabed (between '// &
         'the last node in contact and the next); -1 when none', &
      'dynamic_ends.csv | time_s | s | time of the frame', &
      'dynamic_ends.csv | line | - | line name', &
      'dynamic_ends.csv | end | - | A (S = 0) or B (S = L)', &
      'dynamic_ends.csv | Fx_N | N | x force of the support on the line', &
      'dynamic_ends.csv | Fy_N | N | y force of the support on the line', &
      'dynamic_ends.csv | Fz_N | N | z force of the support on the line', &
      'dynamic_ends.csv | Mx_Nm | N m | x moment of the support on the line', &
      'dynamic_ends.csv | My_Nm | N m | y moment of the support on the line', &
      'dynamic_ends.csv | Mz_Nm | N m | z moment of the support on the line', &
      'dynamic_ends.csv | tension_N | N | magnitude of the support force', &
      'dynamic_ends_step.csv | step | - | step number, 0 for the start', &
      'dynamic_ends_step.csv | time_s | s | time at the end of the step', &
      'dynamic_ends_step.csv | line | - | line name', &
      'dynamic_ends_step.csv | end | - | A (S = 0) or B (S = L)', &
      'dynamic_ends_step.csv | Fx_N | N | x force of the support on the line', &
      'dynamic_ends_step.csv | Fy_N | N | y force of the support on the line', &
      'dynamic_ends_step.csv | Fz_N | N | z force of the support on the line', &
      'dynamic_ends_step.csv | Mx_Nm | N m | x moment of the support on the line', &
      'dynamic_ends_step.csv | My_Nm | N m | y moment of the support on the line', &
      'dynamic_ends_step.csv | Mz_Nm | N m | z moment of the support on the line', &
      'dynamic_ends_step.csv | tension_N | N | magnitude of the support force', &
      'dynamic_waves.csv | time_s | s | time of the frame', &
      'dynamic_waves.csv | probe | - | wave probe name (*WAVE PROBE)', &
      'dynamic_waves.csv | x_m | m | x of the probe, global axes', &
      'dynamic_waves.csv | y_m | m | y of the probe, global axes', &
      'dynamic_waves.csv | elevation_m | m | elevation above still water, ramp included', &
      'dynamic_waves_step.csv | step | - | step number, 0 for the start', &
      'dynamic_waves_step.csv | time_s | s | time at the end of the step', &
      'dynamic_waves_step.csv | probe | - | wave probe name (*WAVE PROBE)', &
      'dynamic_waves_step.csv | x_m | m | x of the probe, global axes', &
      'dynamic_waves_step.csv | y_m | m | y of the probe, global axes', &
      'dynamic_waves_step.csv | elevation_m | m | elevation above still water, ramp included', &
      'dynamic_vessels.csv | time_s | s | time of the frame', &
      'dynamic_vessels.csv | vessel | - | vessel name', &
      'dynamic_vessels.csv | x_m | m | x of the reference point, global axes', &
      'dynamic_vessels.csv | y_m | m | y of the reference point, global axes', &
      'dynamic_vessels.csv | z_m | m | z of the reference point, global axes', &
      'dynamic_vessels.csv | roll_rad | rad | roll of Rv = Rz(yaw) Ry(pitch) Rx(roll)', &
      'dynamic_vessels.csv | pitch_rad | rad | pitch of Rv', &
      'dynamic_vessels.csv | yaw_rad | rad | yaw of Rv, from the mean heading', &
      'dynamic_vessels.csv | heading_rad | rad | mean heading; vessel axes Rz(heading) Rv', &
      'dynamic_vessels.csv | Fx_N | N | x force of the lines on it, global', &
      'dynamic_vessels.csv | Fy_N | N | y force of the lines on it, global', &
      'dynamic_vessels.csv | Fz_N | N | z force of the lines on it, global', &
      'dynamic_vessels.csv | Mx_Nm | N m | x moment about the reference point, global', &
      'dynamic_vessels.csv | My_Nm | N m | y moment about the reference point, global', &
      'dynamic_vessels.csv | Mz_Nm | N m | z moment about the reference point, global', &
      'dynamic_vessels.csv | Fx_vessel_N | N | x force of the lines on it, vessel axes', &
      'dynamic_vessels.csv | Fy_vessel_N | N | y force of the lines on it, vessel axes', &
      'dynamic_vessels.csv | Fz_vessel_N | N | z force of the lines on it, vessel axes', &
      'dynamic_vessels.csv | Mx_vessel_Nm | N m | x moment about it, vessel axes', &
      'dynamic_vessels.csv | My_vessel_Nm | N m | y moment about it, vessel axes', &
      'dynamic_vessels.csv | Mz_vessel_Nm | N m | z moment about it, vessel axes', &
      'dynamic_vessels_step.csv | step | - | step number, 0 for the start', &
      'dynamic_vessels_step.csv | time_s | s | time at the end of the step', &
      'dynamic_vessels_step.csv | vessel | - | vessel name', &
      'dynamic_vessels_step.csv | x_m | m | x of the reference point, global axes', &
      'dynamic_vessels_step.csv | y_m | m | y of the reference point, global axes', &
      'dynamic_vessels_step.csv | z_m | m | z of the reference point, global axes', &
      'dynamic_vessels_step.csv | roll_rad | rad | roll of Rv = Rz(yaw) Ry(pitch) Rx(roll)', &
      'dynamic_vessels_step.csv | pitch_rad | rad | pitch of Rv', &
      'dynamic_vessels_step.csv | yaw_rad | rad | yaw of Rv, from the mean heading', &
      'dynamic_vessels_step.csv | heading_rad | rad | mean heading; vessel axes Rz(heading) Rv', &
      'dynamic_vessels_step.csv | Fx_N | N | x force of the lines on it, global', &
      'dynamic_vessels_step.csv | Fy_N | N | y force of the lines on it, global', &
      'dynamic_vessels_step.csv | Fz_N | N | z force of the lines on it, global', &
      'dynamic_vessels_step.csv | Mx_Nm | N m | x moment about the reference point, global', &
      'dynamic_vessels_step.csv | My_Nm | N m | y moment about the reference point, global', &
      'dynamic_vessels_step.csv | Mz_Nm | N m | z moment about the reference point, global', &
      'dynamic_vessels_step.csv | Fx_vessel_N | N | x force of the lines on it, vessel axes', &
      'dynamic_vessels_step.csv | Fy_vessel_N | N | y force of the lines on it, vessel axes', &
      'dynamic_vessels_step.csv | Fz_vessel_N | N | z force of the lines on it, vessel axes', &
      'dynamic_vessels_step.csv | Mx_vessel_Nm | N m | x moment about it, vessel axes', &
      'dynamic_vessels_step.csv | My_vessel_Nm | N m | y moment about it, vessel axes', &
      'dynamic_vessels_step.csv | Mz_vessel_Nm | N m | z moment about it, vessel axes', &
      'dynamic_connections.csv | time_s | s | time of the frame', &
      'dynamic_connections.csv | vessel | - | vessel name', &
      'dynamic_connections.csv | line | - | line name', &
      'dynamic_connections.csv | end | - | A (S = 0), B (S = L) or the node number', &
      'dynamic_connections.csv | Fx_N | N | x force of the line on it, global', &
      'dynamic_connections.csv | Fy_N | N | y force of the line on it, global', &
      'dynamic_connections.csv | Fz_N | N | z force of the line on it, global', &
      'dynamic_connections.csv | Mx_Nm | N m | x moment of the line, global', &
      'dynamic_connections.csv | My_Nm | N m | y moment of the line, global', &
      'dynamic_connections.csv | Mz_Nm | N m | z moment of the line, global', &
      'dynamic_connections.csv | Fx_vessel_N | N | x force of the line on it, vessel axes', &
      'dynamic_connections.csv | Fy_vessel_N | N | y force of the line on it, vessel axes', &
      'dynamic_connections.csv | Fz_vessel_N | N | z force of the line on it, vessel axes', &
      'dynamic_connections.csv | Mx_vessel_Nm | N m | x moment of the line, vessel axes', &
      'dynamic_connections.csv | My_vessel_Nm | N m | y moment of the line, vessel axes', &
      'dynamic_connections.csv | Mz_vessel_Nm | N m | z moment of the line, vessel axes', &
      'dynamic_connections.csv | tension_N | N | magnitude of the force', &
      'dynamic_connections_step.csv | step | - | step number, 0 for the start', &
      'dynamic_connections_step.csv | time_s | s | time at the end of the step', &
      'dynamic_connections_step.csv | vessel | - | vessel name', &
      'dynamic_connections_step.csv | line | - | line name', &
      'dynamic_connections_step.csv | end | - | A (S = 0), B (S = L) or the node number', &
      'dynamic_connections_step.csv | Fx_N | N | x force of the line on it, global', &
      'dynamic_connections_step.csv | Fy_N | N | y force of the line on it, global', &
      'dynamic_connections_step.csv | Fz_N | N | z force of the line on it, global', &
      'dynamic_connections_step.csv | Mx_Nm | N m | x moment of the line, global', &
      'dynamic_connections_step.csv | My_Nm | N m | y moment of the line, global', &
      'dynamic_connections_step.csv | Mz_Nm | N m | z moment of the line, global', &
      'dynamic_connections_step.csv | Fx_vessel_N | N | x force of the line on it, vessel axes', &
      'dynamic_connections_step.csv | Fy_vessel_N | N | y force of the line on it, vessel axes', &
      'dynamic_connections_step.csv | Fz_vessel_N | N | z force of the line on it, vessel axes', &
      'dynamic_connections_step.csv | Mx_vessel_Nm | N m | x moment of the line, vessel axes', &
      'dynamic_connections_step.csv | My_vessel_Nm | N m | y moment of the line, vessel axes', &
      'dynamic_connections_step.csv | Mz_vessel_Nm | N m | z moment of the line, vessel axes', &
      'dynamic_connections_step.csv | tension_N | N | magnitude of the force', &
      'dynamic_bodies.csv | time_s | s | time of the frame', &
      'dynamic_bodies.csv | body | - | body name', &
      'dynamic_bodies.csv | x_m | m | x of the reference point R, global axes', &
      'dynamic_bodies.csv | y_m | m | y of R, global axes', &
      'dynamic_bodies.csv | z_m | m | z of R, global axes', &
      'dynamic_bodies.csv | rx_rad | rad | rotation vector from the start, x', &
      'dynamic_bodies.csv | ry_rad | rad | rotation vector from the start, y', &
      'dynamic_bodies.csv | rz_rad | rad | rotation vector from the start, z', &
      'dynamic_bodies.csv | Fx_N | N | x force of the lines on the body', &
      'dynamic_bodies.csv | Fy_N | N | y force of the lines on the body', &
      'dynamic_bodies.csv | Fz_N | N | z force of the lines on the body', &
      'dynamic_bodies.csv | Mx_Nm | N m | x moment of the lines about R', &
      'dynamic_bodies.csv | My_Nm | N m | y moment of the lines about R', &
      'dynamic_bodies.csv | Mz_Nm | N m | z moment of the lines about R', &
      'dynamic_bodies_step.csv | step | - | step number, 0 for the start', &
      'dynamic_bodies_step.csv | time_s | s | time at the end of the step', &
      'dynamic_bodies_step.csv | body | - | body name', &
      'dynamic_bodies_step.csv | x_m | m | x of the reference point R, global axes', &
      'dynamic_bodies_step.csv | y_m | m | y of R, global axes', &
      'dynamic_bodies_step.csv | z_m | m | z of R, global axes', &
      'dynamic_bodies_step.csv | rx_rad | rad | rotation vector from the start, x', &
      'dynamic_bodies_step.csv | ry_rad | rad | rotation vector from the start, y', &
      'dynamic_bodies_step.csv | rz_rad | rad | rotation vector from the start, z', &
      'dynamic_bodies_step.csv | Fx_N | N | x force of the lines on the body', &
      'dynamic_bodies_step.csv | Fy_N | N | y force of the lines on the body', &
      'dynamic_bodies_step.csv | Fz_N | N | z force of the lines on the body', &
      'dynamic_bodies_step.csv | Mx_Nm | N m | x moment of the lines about R', &
      'dynamic_bodies_step.csv | My_Nm | N m | y moment of the lines about R', &
      'dynamic_bodies_step.csv | Mz_Nm | N m | z moment of the lines about R', &
      'dynamic_log.csv | step | - | step number, from 1', &
      'dynamic_log.csv | time_s | s | time at the end of the step', &
      'dynamic_log.csv | dt_s | s | step length used', &
      'dynamic_log.csv | iterations | - | Newton iterations of the step', &
      'dynamic_log.csv | cutbacks | - | halvings the step needed', &
      'dynamic_log.csv | kinetic_J | J | kinetic energy', &
      'dynamic_log.csv | strain_J | J | stored (strain) energy', &
      'dynamic_log.csv | gravity_J | J | potential of the weight', &
      'dynamic_log.csv | external_work_J | J | work of prescribed motions and loads since t = 0', &
      'dynamic_log.csv | damping_work_J | J | energy taken out by damping since t = 0: '// &
         '*DAMPING and the sections'' structural damping', &
      'dynamic_log.csv | hydro_work_J | J | work of the water since t = 0', &
      'dynamic_log.csv | seabed_work_J | J | work of the seabed since t = 0', &
      'dynamic_log.csv | numerical_work_J | J | work of the dissipative EMC''s '// &
         'numerical stress since t = 0 (0 without RHO INF < 1)', &
      'dynamic_log.csv | numerical_energy_J | J | numerical energy N of the '// &
         'dissipative EMC at the end of the step; total + N never grows in free flight', &
      'dynamic_log.csv | total_J | J | kinetic + strain + gravity', &
      'dynamic_log.csv | px | kg m/s | x of the total linear momentum', &
      'dynamic_log.csv | py | kg m/s | y of the total linear momentum', &
      'dynamic_log.csv | pz | kg m/s | z of the total linear momentum', &
      'dynamic_log.csv | Lx | kg m2/s | x of the total angular momentum about the origin', &
      'dynamic_log.csv | Ly | kg m2/s | y of the total angular momentum about the origin', &
      'dynamic_log.csv | Lz | kg m2/s | z of the total angular momentum about the origin']
   !> Every table's columns: 'file | column | unit | meaning'
   character(len=row_len), parameter :: output_columns(*) = [static_columns, dynamic_columns]

   !> Every key of status.txt, in the order written: 'status.txt | key | unit | meaning'
   !> (NAME: one key per table or deck parameter). rodyn_output's output_write_status
   !> writes them; docs/output.md lists the same keys (check_output_schema.py).
   character(len=row_len), parameter :: status_keys(*) = [character(len=row_len) :: &
      'status.txt | complete | - | true when all the deck asks for is done, else false', &
      'status.txt | status | - | complete, running, statics complete, dynamics to run, '// &
      'or what failed', &
      'status.txt | load_factor | - | static load factor reached (1 for a complete static run)', &
      'status.txt | increments | - | static load increments converged', &
      'status.txt | iterations | - | Newton iterations of the static analysis', &
      'status.txt | cutbacks | - | static increment halvings', &
      'status.txt | wall_time_s | s | wall time of the solve (static and dynamic)', &
      'status.txt | dynamic | - | true (dynamic runs only, as the keys down to committed_bytes)', &
      'status.txt | time_reached_s | s | last time reached (running: of the last frame written)', &
      'status.txt | steps | - | time steps completed', &
      'status.txt | step_iterations | - | Newton iterations over all steps', &
      'status.txt | step_tangents | - | tangents formed and factorised over all steps', &
      'status.txt | step_cutbacks | - | step halvings in total', &
      'status.txt | frames | - | output frames committed (in the tables and dynamic.h5)', &
      'status.txt | committed_bytes.NAME | bytes | size of CSV table NAME at the last sync', &
      'status.txt | rodyn_version | - | program version', &
      'status.txt | deck | - | path of the main deck file', &
      'status.txt | parameter.NAME | - | deck parameter NAME as substituted, one key each']

   !> The datasets of /environment in results.h5 and dynamic.h5 (with *WATER; current_*
   !> with a current, seabed_* with a seabed; written by rodyn_output_common's
   !> write_environment_h5, their units those of environment.csv): 'files | path | units
   !> | description'.
   character(len=row_len), parameter :: environment_datasets(*) = [character(len=row_len) :: &
      'results.h5, dynamic.h5 | /environment/surface_z | m | '// &
         'z of the still water level', &
      'results.h5, dynamic.h5 | /environment/depth | m | '// &
         'water depth at x = y = 0', &
      'results.h5, dynamic.h5 | /environment/density | kg/m3 | '// &
         'sea water density', &
      'results.h5, dynamic.h5 | /environment/current_ramp | s | '// &
         'ramp-in duration of the current in dynamics', &
      'results.h5, dynamic.h5 | /environment/current_z | m | '// &
         'levels of the current profile, increasing', &
      'results.h5, dynamic.h5 | /environment/current_speed | m/s | '// &
         'current speed at the levels (linear between, constant beyond)', &
      'results.h5, dynamic.h5 | /environment/current_heading | deg | '// &
         'direction the current flows towards, from +x towards +y', &
      'results.h5, dynamic.h5 | /environment/seabed_slope | deg | '// &
         'angle of the seabed plane', &
      'results.h5, dynamic.h5 | /environment/seabed_slope_dir | deg | '// &
         'heading of steepest ascent, from +x towards +y', &
      'results.h5, dynamic.h5 | /environment/seabed_stiffness | N/m3 | '// &
         'normal stiffness per contact area', &
      'results.h5, dynamic.h5 | /environment/seabed_damping | Pa s/m | '// &
         'normal damping per contact area', &
      'results.h5, dynamic.h5 | /environment/seabed_mu_axial | - | '// &
         'axial friction coefficient', &
      'results.h5, dynamic.h5 | /environment/seabed_mu_lateral | - | '// &
         'lateral friction coefficient', &
      'results.h5, dynamic.h5 | /environment/seabed_v_mob | m/s | '// &
         'friction mobilisation velocity']

   !> The attributes of the groups of results.h5 and dynamic.h5 (and the end_held of
   !> reactions): 'file | object:attribute | unit | meaning', LINE standing for a line's
   !> group, NAME for a deck parameter (the `units` and `description` of each dataset
   !> are those of output_datasets).
   character(len=row_len), parameter :: output_attributes(*) = [character(len=row_len) :: &
      'results.h5 | /:program | - | program name: rodyn', &
      'results.h5 | /:version | - | program version', &
      'results.h5 | /:deck_file | - | path of the main deck file', &
      'results.h5 | /:title | - | *HEADING title', &
      'results.h5 | /:units | - | the unit system: SI (m, s, kg, N, N m, rad)', &
      'results.h5 | /:complete | - | 1 if the static analysis reached its end, else 0', &
      'results.h5 | /:status | - | the static analysis: complete, or what failed '// &
      '(running while it runs)', &
      'results.h5 | /static:load_factor | - | static load factor reached', &
      'results.h5 | /static:increments | - | load increments converged', &
      'results.h5 | /static:iterations | - | Newton iterations in total', &
      'results.h5 | /static:cutbacks | - | increment halvings', &
      'results.h5 | /static:wall_time_s | s | solve wall time', &
      'results.h5 | /modes:solver | - | the eigensolver of *MODAL: DENSE (LAPACK) or '// &
         'LANCZOS (ARPACK)', &
      'results.h5 | /modes:tangent_asymmetry | - | |K - K^T| / |K| of the tangent, '// &
         'estimated; the modes are those of its symmetric part', &
      'results.h5 | /static/LINE:name | - | the line name', &
      'results.h5 | /static/LINE:touchdown_s | m | largest S in contact with the seabed '// &
         '(between the last node in contact and the next); -1 when none', &
      'results.h5 | /static/LINE/reactions:end_held | - | 1 where end A, B is held, else 0', &
      'results.h5 | /environment:seabed | - | 1 when a seabed is modelled, else 0', &
      'results.h5 | /parameters:NAME | - | deck parameter NAME as used (number or text)', &
      'dynamic.h5 | /:program | - | program name: rodyn', &
      'dynamic.h5 | /:version | - | program version', &
      'dynamic.h5 | /:deck_file | - | path of the main deck file', &
      'dynamic.h5 | /:title | - | *HEADING title', &
      'dynamic.h5 | /:units | - | the unit system: SI (m, s, kg, N, N m, rad)', &
      'dynamic.h5 | /:complete | - | 1 if the analysis reached its end, else 0', &
      'dynamic.h5 | /:status | - | one line: complete, or what failed (running while it runs)', &
      'dynamic.h5 | /:scheme | - | time integration scheme (EMC, ...)', &
      'dynamic.h5 | /:rho_inf | - | RHO INF of *DYNAMIC: ALPHA''s spectral radius at '// &
         'infinite frequency, or the dissipative EMC''s (1: EMC conserving)', &
      'dynamic.h5 | /:dt | s | *DYNAMIC DT', &
      'dynamic.h5 | /dynamic:duration_s | s | *DYNAMIC TIME', &
      'dynamic.h5 | /dynamic:output_interval_s | s | *DYNAMIC OUTPUT INTERVAL', &
      'dynamic.h5 | /dynamic:ramp_s | s | longest ramp-in of the motions, waves '// &
         'and current (0: none)', &
      'dynamic.h5 | /dynamic:frames | - | frames written (at close)', &
      'dynamic.h5 | /dynamic:steps | - | time steps completed (at close)', &
      'dynamic.h5 | /dynamic:time_reached_s | s | last time reached (at close)', &
      'dynamic.h5 | /dynamic:step_iterations | - | Newton iterations over all steps', &
      'dynamic.h5 | /dynamic:step_tangents | - | tangents formed over all steps', &
      'dynamic.h5 | /dynamic:step_cutbacks | - | step halvings in total', &
      'dynamic.h5 | /dynamic:wall_time_s | s | wall time of the run (at close)', &
      'dynamic.h5 | /dynamic/LINE:name | - | the line name', &
      'dynamic.h5 | /dynamic/LINE/reactions:end_held | - | 1 where end A, B is held, else 0', &
      'dynamic.h5 | /dynamic/LINE/step_reactions:end_held | - | as reactions', &
      'dynamic.h5 | /dynamic/sea:probes | - | names of the probes, comma-separated', &
      'dynamic.h5 | /dynamic/sea:vessels | - | names of the vessels, comma-separated', &
      'dynamic.h5 | /dynamic/sea:connections | - | VESSEL/LINE/END of each connection', &
      'dynamic.h5 | /dynamic/sea:bodies | - | names of the bodies, comma-separated', &
      'dynamic.h5 | /environment:seabed | - | 1 when a seabed is modelled, else 0', &
      'dynamic.h5 | /parameters:NAME | - | deck parameter NAME as used (number or text)']

   !> Every HDF5 dataset of results.h5 and dynamic.h5 but those of /environment (which
   !> come with environment_items, rodyn_output_common): 'file | path | units |
   !> description', LINE standing for a line's group; written as the attributes `units`
   !> and `description` of the dataset (rodyn_output_common's describe).
   character(len=row_len), parameter :: output_datasets(*) = [character(len=row_len) :: &
      'results.h5 | /deck | - | full text of the input deck, includes expanded', &
      'results.h5 | /static/LINE/curvature | 1/m | section-frame curvatures, '// &
         'columns K1 (about d1), K2 (about d2), K3 (twist)', &
      'results.h5 | /static/LINE/effective_tension | N | effective tension N3 '// &
         'along d3, positive in tension', &
      'results.h5 | /static/LINE/gp_element | - | element of each integration '// &
         'point, numbered from 1 along the line', &
      'results.h5 | /static/LINE/gp_point | - | integration point number within '// &
         'its element, from 1', &
      'results.h5 | /static/LINE/gp_s | m | unstretched arc length of the '// &
         'integration points', &
      'results.h5 | /static/LINE/moment | N m | bending moments, columns M1 '// &
         'about d1, M2 about d2', &
      'results.h5 | /static/LINE/node_s | m | unstretched arc length of the '// &
         'nodes', &
      'results.h5 | /static/LINE/node_xyz | m | node positions, one row per '// &
         'node, columns x, y, z (global axes)', &
      'results.h5 | /static/LINE/reactions | N (columns 1-3), N m (columns 4-6) '// &
         '| force and moment of the support on the line, global axes; rows end A, '// &
         'end B; columns Fx, Fy, Fz, Mx, My, Mz; zero where end_held is 0', &
      'results.h5 | /modes/period_s | s | natural periods (*MODAL), longest first', &
      'results.h5 | /modes/frequency_hz | Hz | natural frequencies', &
      'results.h5 | /modes/omega_rad_s | rad/s | natural circular frequencies', &
      'results.h5 | /modes/LINE/ux | m | (node, mode) x translation of the node in each '// &
         'mode, largest translation of the system 1 m', &
      'results.h5 | /modes/LINE/uy | m | (node, mode) y translation of the node in each '// &
         'mode, largest translation of the system 1 m', &
      'results.h5 | /modes/LINE/uz | m | (node, mode) z translation of the node in each '// &
         'mode, largest translation of the system 1 m', &
      'results.h5 | /modes/LINE/rx | rad | (node, mode) rotation about x of the node in each '// &
         'mode, largest translation of the system 1 m', &
      'results.h5 | /modes/LINE/ry | rad | (node, mode) rotation about y of the node in each '// &
         'mode, largest translation of the system 1 m', &
      'results.h5 | /modes/LINE/rz | rad | (node, mode) rotation about z of the node in each '// &
         'mode, largest translation of the system 1 m', &
      'results.h5 | /static/LINE/seabed_friction | N/m | magnitude of the '// &
         'seabed friction force per unit length at the nodes', &
      'results.h5 | /static/LINE/seabed_normal | N/m | seabed normal contact '// &
         'force per unit length at the nodes (0: no contact)', &
      'results.h5 | /static/LINE/shear | N | shear forces, columns N1 along d1, '// &
         'N2 along d2', &
      'results.h5 | /static/LINE/torque | N m | torsional moment M3 about d3', &
      'results.h5 | /static/LINE/wall_tension | N | wall (true) tension, T_eff '// &
         '+ p_i A_i - p_o A_o, positive in tension', &
      'dynamic.h5 | /deck | - | full text of the input deck, includes expanded', &
      'dynamic.h5 | /dynamic/LINE/bending_curvature | 1/m | total bending '// &
         'curvature sqrt(K1^2 + K2^2); row per frame', &
      'dynamic.h5 | /dynamic/LINE/effective_tension | N | effective tension N3 '// &
         'along d3, positive in tension; row per frame', &
      'dynamic.h5 | /dynamic/LINE/end_tension | N | magnitude of the support '// &
         'force, sqrt(Fx^2 + Fy^2 + Fz^2); row per frame; columns end A, end B', &
      'dynamic.h5 | /dynamic/LINE/gp_element | - | element of each integration '// &
         'point, numbered from 1 along the line', &
      'dynamic.h5 | /dynamic/LINE/gp_point | - | integration point number '// &
         'within its element, from 1', &
      'dynamic.h5 | /dynamic/LINE/gp_s | m | unstretched arc length of the '// &
         'integration points', &
      'dynamic.h5 | /dynamic/LINE/moment_1 | N m | bending moment M1 about d1; '// &
         'row per frame', &
      'dynamic.h5 | /dynamic/LINE/moment_2 | N m | bending moment M2 about d2; '// &
         'row per frame', &
      'dynamic.h5 | /dynamic/LINE/node_s | m | unstretched arc length of the '// &
         'nodes', &
      'dynamic.h5 | /dynamic/LINE/reactions | N (columns 1-3, 7-9), N m (4-6, '// &
         '10-12) | force and moment of the support on the line, global axes; row '// &
         'per frame; columns Fx, Fy, Fz, Mx, My, Mz at end A, then at end B; zero '// &
         'at a free end', &
      'dynamic.h5 | /dynamic/LINE/seabed_friction | N/m | magnitude of the '// &
         'seabed friction force per unit length at the nodes; row per frame', &
      'dynamic.h5 | /dynamic/LINE/seabed_normal | N/m | seabed normal contact '// &
         'force per unit length at the nodes; row per frame', &
      'dynamic.h5 | /dynamic/LINE/step_end_tension | N | magnitude of the '// &
         'support force at the times of step_time (every step); columns end A, end '// &
         'B', &
      'dynamic.h5 | /dynamic/LINE/step_reactions | N (columns 1-3, 7-9), N m '// &
         '(4-6, 10-12) | force and moment of the support on the line, global axes, '// &
         'at the times of step_time (every step); columns as reactions', &
      'dynamic.h5 | /dynamic/LINE/step_time | s | time of each row of '// &
         'step_reactions and step_end_tension: 0, then the end of each step', &
      'dynamic.h5 | /dynamic/LINE/torque | N m | torsional moment M3 about d3; '// &
         'row per frame', &
      'dynamic.h5 | /dynamic/LINE/touchdown_s | m | largest arc length in '// &
         'contact with the seabed, -1 when none; one value per frame', &
      'dynamic.h5 | /dynamic/LINE/wall_tension | N | wall (true) tension, T_eff '// &
         '+ p_i A_i - p_o A_o, positive in tension; row per frame', &
      'dynamic.h5 | /dynamic/LINE/x | m | x of the nodes (global axes); row per '// &
         'frame', &
      'dynamic.h5 | /dynamic/LINE/y | m | y of the nodes (global axes); row per '// &
         'frame', &
      'dynamic.h5 | /dynamic/LINE/z | m | z of the nodes (global axes); row per '// &
         'frame', &
      'dynamic.h5 | /dynamic/log/angular_momentum | kg m2/s | total angular '// &
         'momentum about the origin; columns x, y, z (global axes)', &
      'dynamic.h5 | /dynamic/log/cutbacks | - | halvings needed by the step', &
      'dynamic.h5 | /dynamic/log/damping_work | J | energy taken out by damping '// &
         'since t = 0: *DAMPING and the sections'' structural damping', &
      'dynamic.h5 | /dynamic/log/dt | s | step length used', &
      'dynamic.h5 | /dynamic/log/numerical_energy | J | numerical energy N of '// &
         'the dissipative EMC at the end of the step', &
      'dynamic.h5 | /dynamic/log/numerical_work | J | work of the dissipative '// &
         'EMC''s numerical stress since t = 0', &
      'dynamic.h5 | /dynamic/log/external_work | J | work done on the line '// &
         'since t = 0 by prescribed motions and loads', &
      'dynamic.h5 | /dynamic/log/gravity | J | potential of the weight', &
      'dynamic.h5 | /dynamic/log/hydro_work | J | work done on the line since t '// &
         '= 0 by the water: buoyancy, drag, added mass', &
      'dynamic.h5 | /dynamic/log/iterations | - | Newton iterations of the step', &
      'dynamic.h5 | /dynamic/log/kinetic | J | kinetic energy', &
      'dynamic.h5 | /dynamic/log/momentum | kg m/s | total linear momentum; '// &
         'columns x, y, z (global axes)', &
      'dynamic.h5 | /dynamic/log/seabed_work | J | work done on the line since '// &
         't = 0 by the seabed: contact, damping, friction', &
      'dynamic.h5 | /dynamic/log/step | - | step number, from 1', &
      'dynamic.h5 | /dynamic/log/strain | J | stored (strain) energy', &
      'dynamic.h5 | /dynamic/log/time | s | time at the end of the step', &
      'dynamic.h5 | /dynamic/log/total | J | kinetic + strain + gravity', &
      'dynamic.h5 | /dynamic/sea/probe_xy | m | the points of the wave probes, a row '// &
         'per probe (attribute probes); columns x, y (global axes)', &
      'dynamic.h5 | /dynamic/sea/probe_elevation | m | wave elevation above the '// &
         'still water level at each probe (attribute probes); row per frame', &
      'dynamic.h5 | /dynamic/sea/vessel_motion | m (x, y, z), rad (roll, pitch, yaw, '// &
         'heading) | per vessel (attribute vessels) 7 columns: reference point x, y, '// &
         'z (global), roll, pitch, yaw of Rv, mean heading; row per frame', &
      'dynamic.h5 | /dynamic/sea/vessel_load | N (Fx, Fy, Fz), N m (Mx, My, Mz) | per '// &
         'vessel 12 columns: force of its lines on it and moment about its reference '// &
         'point, global axes, then vessel axes; row per frame', &
      'dynamic.h5 | /dynamic/sea/connection_load | N (Fx, Fy, Fz, tension), N m (Mx, '// &
         'My, Mz) | per connection (attribute connections) 13 columns: force and '// &
         'moment of the line on the vessel, global then vessel axes, |F|; row per frame', &
      'dynamic.h5 | /dynamic/sea/step_probe_elevation | m | as probe_elevation, at '// &
         'the times of step_time (every step)', &
      'dynamic.h5 | /dynamic/sea/step_vessel_motion | m (x, y, z), rad (roll, pitch, '// &
         'yaw, heading) | as vessel_motion, at the times of step_time (every step)', &
      'dynamic.h5 | /dynamic/sea/step_vessel_load | N (Fx, Fy, Fz), N m (Mx, My, Mz) '// &
         '| as vessel_load, at the times of step_time (every step)', &
      'dynamic.h5 | /dynamic/sea/step_connection_load | N (Fx, Fy, Fz, tension), N m '// &
         '(Mx, My, Mz) | as connection_load, at the times of step_time (every step)', &
      'dynamic.h5 | /dynamic/sea/body_motion | m (x, y, z), rad (rx, ry, rz), N (Fx, '// &
         'Fy, Fz), N m (Mx, My, Mz) | per frame, 12 values per body: R, the rotation '// &
         'vector, the force of the lines and their moment about R, global axes', &
      'dynamic.h5 | /dynamic/sea/step_body_motion | m (x, y, z), rad (rx, ry, rz), N '// &
         '(Fx, Fy, Fz), N m (Mx, My, Mz) | as body_motion, at the times of step_time '// &
         '(every step)', &
      'dynamic.h5 | /dynamic/sea/step_time | s | time of each row of the step_ '// &
         'datasets of /dynamic/sea: 0, then the end of each step', &
      'dynamic.h5 | /dynamic/time | s | time of each output frame']

contains

   !> Field k (1: file, 2: column, 3: unit, 4: meaning) of a row of output_columns,
   !> without the blanks around it.
   pure function schema_field(row, k) result(s)
      character(len=*), intent(in) :: row   !< a row of output_columns
      integer, intent(in) :: k              !< field number, 1 to 4
      character(len=:), allocatable :: s    !< the field
      integer :: i, a, b
      a = 1
      do i = 1, k - 1
         b = index(row(a:), '|')
         if (b == 0) then
            s = ''
            return
         end if
         a = a + b
      end do
      b = index(row(a:), '|')
      if (b == 0 .or. k == 4) then
         s = trim(adjustl(row(a:)))
      else
         s = trim(adjustl(row(a:a + b - 2)))
      end if
   end function schema_field

   !> The row of output_datasets for dataset `path` of file `file` ('' when none): a
   !> line's dataset is looked up with its group name replaced by LINE, from `line_group`
   !> ('/static/RISER': '/static/LINE/node_s' for '/static/RISER/node_s').
   pure function schema_dataset(file, path, line_group) result(row)
      character(len=*), intent(in) :: file                 !< 'results.h5', 'dynamic.h5'
      character(len=*), intent(in) :: path                 !< dataset path in the file
      character(len=*), intent(in), optional :: line_group !< group of the line, if any
      character(len=:), allocatable :: row                 !< the row, or ''
      character(len=:), allocatable :: key, needle
      integer :: k
      key = path
      if (present(line_group)) then
         if (index(path, line_group//'/') == 1) key = &
            line_group(:index(line_group, '/', back=.true.))//'LINE'//path(len(line_group) + 1:)
      end if
      row = ''
      ! every row begins 'file | key |' (test_output's test_schema_rows_found holds the
      ! table to it): compared in place, not field by field (cutting every row's fields
      ! out would cost a good part of a short run)
      needle = file//' | '//key//' |'
      if (len(needle) > row_len) return
      do k = 1, size(output_datasets)
         if (output_datasets(k)(1:len(needle)) == needle) then
            row = trim(output_datasets(k))
            return
         end if
      end do
   end function schema_dataset

   !> The row of environment_datasets for dataset `path` ('/environment/depth'); ''
   !> when none.
   pure function schema_environment(path) result(row)
      character(len=*), intent(in) :: path   !< dataset path
      character(len=:), allocatable :: row   !< the row, or ''
      integer :: k
      row = ''
      do k = 1, size(environment_datasets)
         if (schema_field(environment_datasets(k), 2) == path) then
            row = trim(environment_datasets(k))
            return
         end if
      end do
   end function schema_environment

   !> The header row of CSV table `file`: its column names, comma-separated, in order
   !> ('' for a file the schema does not know).
   pure function schema_header(file) result(s)
      character(len=*), intent(in) :: file  !< 'dynamic_nodes.csv', ...
      character(len=:), allocatable :: s    !< 'time_s,line,node,...'
      integer :: k
      s = ''
      do k = 1, size(output_columns)
         if (schema_field(output_columns(k), 1) /= file) cycle
         if (len(s) > 0) s = s//','
         s = s//schema_field(output_columns(k), 2)
      end do
   end function schema_header

   !> The files of the schema, each once, in the order of output_columns, as one
   !> comma-separated text.
   pure function schema_tables() result(s)
      character(len=:), allocatable :: s    !< 'static_nodes.csv,static_elements.csv,...'
      character(len=:), allocatable :: file
      integer :: k
      s = ','
      do k = 1, size(output_columns)
         file = schema_field(output_columns(k), 1)
         if (index(s, ','//file//',') == 0) s = s//file//','
      end do
      s = s(2:len(s) - 1)
   end function schema_tables
end module rodyn_output_schema
