#!/bin/sh
lepp audit --engine cgal --method centroid --theta 20 --timeout 5 --inputs corpus/audits/cgal/min-angle-4/input.poly
