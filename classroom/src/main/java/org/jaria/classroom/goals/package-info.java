/** Assignment 3: named goals with sonar localization and path planning. */
package org.jaria.classroom.goals;
