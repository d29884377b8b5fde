/** Assignment 4: follow a coloured ball with ACTS. */
package org.jaria.classroom.ball;
