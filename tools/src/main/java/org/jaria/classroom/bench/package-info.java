/** {@code jaria bench grade}: how long a class takes to grade, and that jobs do not change it. */
package org.jaria.classroom.bench;
