/**
 * Robot parameter files ({@code .p}): {@link org.jaria.params.ParamFile} reads and writes the
 * generic INI-like format, {@link org.jaria.params.ArRobotParams} gives the typed values ARIA uses
 * (size, speed limits, conversion factors, sonar and IR geometry), layered as ARIA loads them:
 * built-in defaults, then the model's file ({@code p3dx-sh.p}, shipped with JAria), then the file
 * named after the individual robot.
 */
package org.jaria.params;
