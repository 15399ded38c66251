#!/bin/sh
lepp audit --engine cgal --method centroid --theta 33 --timeout 5 --inputs corpus/audits/cgal/min-angle-2/input.poly
